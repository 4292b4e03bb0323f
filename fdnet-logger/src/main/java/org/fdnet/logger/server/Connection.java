package org.fdnet.logger.server;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.net.SocketException;
import java.net.SocketTimeoutException;
import org.fdnet.event.wire.ErrorCode;
import org.fdnet.event.wire.ErrorFrame;
import org.fdnet.event.wire.Frame;
import org.fdnet.event.wire.FrameReader;
import org.fdnet.event.wire.FrameWriter;
import org.fdnet.event.wire.Hello;
import org.fdnet.event.wire.Protocol;
import org.fdnet.event.wire.ProtocolException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The third layer of the thesis's server (server → factory → connection): one client, served on its own
 * thread. This class does what both servers share — the handshake (HELLO with magic, version, role), the
 * state the panels show, and the rule that any protocol violation closes this one connection with a
 * logged reason and an ERROR frame; the subclasses (receiver for cores, sender for viewers) serve the
 * frames after the handshake.
 */
public abstract class Connection implements Runnable {
    private static final Logger LOG = LoggerFactory.getLogger(Connection.class);
    private static final int HANDSHAKE_TIMEOUT_MILLIS = 10_000;

    protected final Socket socket;
    private final int maxFrameBytes;
    private final FrameWriter writer = new FrameWriter();
    private OutputStream out;
    private volatile ConnectionState state = ConnectionState.WAITING;
    private volatile String name = "";
    private volatile String endReason = "";
    protected volatile long frames;

    protected Connection(Socket socket, int maxFrameBytes) {
        this.socket = socket;
        this.maxFrameBytes = maxFrameBytes;
    }

    public ClientInfo info() {
        return new ClientInfo(socket.getInetAddress().getHostAddress(), socket.getPort(), name, state, frames, endReason);
    }

    public ConnectionState state() {
        return state;
    }

    protected void state(ConnectionState s) {
        state = s;
    }

    protected String describe() {
        return getClass().getSimpleName() + " " + socket.getRemoteSocketAddress() + (name.isEmpty() ? "" : " (" + name + ")");
    }

    @Override
    public final void run() {
        try {
            socket.setTcpNoDelay(true);
            out = new BufferedOutputStream(socket.getOutputStream(), 1 << 16);
            FrameReader in = new FrameReader(new BufferedInputStream(socket.getInputStream(), 1 << 16), maxFrameBytes);
            socket.setSoTimeout(HANDSHAKE_TIMEOUT_MILLIS);
            Frame first = in.read();
            if (first == null) {
                endReason = "closed before the handshake";
                return;
            }
            Hello hello = Hello.read(first);
            if (hello.version() != Protocol.VERSION) {
                refuse(ErrorCode.VERSION, "protocol version " + hello.version() + " not supported; this logger speaks "
                        + "version " + Protocol.VERSION + " (update the peer to the same FDNet release)");
                return;
            }
            name = hello.name();
            socket.setSoTimeout(0);
            if (!handshake(hello)) {
                return;
            }
            state = ConnectionState.ACTIVATED;
            serve(in);
            endReason = endReason.isEmpty() ? "closed by the client" : endReason;
        } catch (ProtocolException e) {
            LOG.warn("closing {}: {}", describe(), e.getMessage());
            refuse(ErrorCode.PROTOCOL, e.getMessage());
        } catch (SocketTimeoutException e) {
            LOG.warn("closing {}: no HELLO within {} ms", describe(), HANDSHAKE_TIMEOUT_MILLIS);
            endReason = "no HELLO within " + HANDSHAKE_TIMEOUT_MILLIS + " ms";
        } catch (SocketException e) {
            endReason = endReason.isEmpty() ? "connection closed: " + e.getMessage() : endReason;
            LOG.info("{} ended: {}", describe(), endReason);
        } catch (IOException e) {
            endReason = endReason.isEmpty() ? e.getMessage() : endReason;
            LOG.info("{} ended: {}", describe(), endReason);
        } catch (InterruptedException e) {
            endReason = "server stopping";
            Thread.currentThread().interrupt();
        } catch (RuntimeException e) {
            LOG.error("internal error serving {}", describe(), e);
            refuse(ErrorCode.INTERNAL, "internal error: " + e);
        } finally {
            state = ConnectionState.STOPPED;
            closed();
            close();
        }
    }

    /** Checks the role and answers WELCOME (true) or refuses (false). */
    protected abstract boolean handshake(Hello hello) throws IOException;

    /** Serves frames until the client closes ({@code read()} returns null) or something fails. */
    protected abstract void serve(FrameReader in) throws IOException, InterruptedException;

    /** Called once when the connection ends, before the socket closes. */
    protected void closed() {
    }

    /** Builds and sends one frame; safe from any thread. */
    protected final void send(FrameBuilder frame) throws IOException {
        synchronized (writer) {
            frame.build(writer);
            writer.writeTo(out);
            out.flush();
        }
    }

    /** Builds one frame of a frame sequence without flushing. */
    protected final void sendUnflushed(FrameBuilder frame) throws IOException {
        synchronized (writer) {
            frame.build(writer);
            writer.writeTo(out);
        }
    }

    /** How a frame is built into the connection's writer. */
    @FunctionalInterface
    protected interface FrameBuilder {
        void build(FrameWriter w);
    }

    /** Sends an ERROR (best effort) and closes. */
    public final void refuse(ErrorCode code, String message) {
        endReason = message;
        try {
            if (out != null) {
                send(w -> new ErrorFrame(code, message).write(w));
            }
        } catch (IOException e) {
            LOG.debug("could not tell {} why it is closed: {}", describe(), e.getMessage());
        }
        close();
    }

    public final void close() {
        try {
            socket.close();
        } catch (IOException e) {
            LOG.debug("closing {}: {}", describe(), e.getMessage());
        }
    }
}

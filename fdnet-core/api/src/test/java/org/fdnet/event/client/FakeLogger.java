package org.fdnet.event.client;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.wire.EventCodec;
import org.fdnet.event.wire.Frame;
import org.fdnet.event.wire.FrameReader;
import org.fdnet.event.wire.FrameWriter;
import org.fdnet.event.wire.Hello;
import org.fdnet.event.wire.MessageType;
import org.fdnet.event.wire.Protocol;

/**
 * A unit seam for the client: speaks the logger protocol on 127.0.0.1, keeps events by sequence number
 * (dropping repeats, as the logger does) and acknowledges each frame at once, as if committed.
 */
final class FakeLogger implements AutoCloseable {
    private final ServerSocket server;
    private final List<NetworkEvent> received = new ArrayList<>();
    private final Thread thread;
    private volatile Socket current;

    FakeLogger(int port) throws IOException {
        this(port, List.of());
    }

    /** A logger whose database already holds {@code committed} (a restarted logger). */
    FakeLogger(int port, List<NetworkEvent> committed) throws IOException {
        received.addAll(committed);
        server = new ServerSocket(port, 10, InetAddress.getLoopbackAddress());
        thread = new Thread(this::serve, "fake-logger");
        thread.setDaemon(true);
        thread.start();
    }

    int port() {
        return server.getLocalPort();
    }

    synchronized List<NetworkEvent> received() {
        return new ArrayList<>(received);
    }

    private void serve() {
        while (!server.isClosed()) {
            try (Socket s = server.accept()) {
                current = s;
                FrameReader in = new FrameReader(new BufferedInputStream(s.getInputStream()), Protocol.DEFAULT_MAX_FRAME_BYTES);
                OutputStream out = new BufferedOutputStream(s.getOutputStream());
                FrameWriter w = new FrameWriter();
                Hello.read(in.read());
                synchronized (this) {
                    w.begin(MessageType.WELCOME).putShort(Protocol.VERSION).putLong(received.size());
                }
                w.writeTo(out);
                out.flush();
                Frame f;
                while ((f = in.read()) != null) {
                    long first = f.getLong();
                    int n = f.getCount(EventCodec.MIN_EVENT_BYTES);
                    synchronized (this) {
                        for (int i = 0; i < n; i++) {
                            NetworkEvent e = EventCodec.read(f);
                            if (first + i == received.size() + 1) {
                                received.add(e);
                            }
                        }
                        w.begin(MessageType.ACK).putLong(received.size());
                    }
                    w.writeTo(out);
                    out.flush();
                }
            } catch (IOException e) {
                // the client went away or the server closed: accept the next one
            }
        }
    }

    @Override
    public void close() throws IOException {
        server.close();
        if (current != null) {
            current.close();
        }
    }
}

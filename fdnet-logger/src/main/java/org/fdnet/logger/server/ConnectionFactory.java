package org.fdnet.logger.server;

import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.util.ArrayList;
import java.util.Iterator;
import java.util.List;
import java.util.function.Function;
import org.fdnet.event.wire.ErrorCode;
import org.fdnet.event.wire.ErrorFrame;
import org.fdnet.event.wire.FrameWriter;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The second layer (thesis, chapter 4 V): receives every client the server accepts, creates its connection
 * through the constructor it was given (the only part that differs between the receiver and the sender),
 * runs it on its own thread, limits how many are served at once and keeps them all visible with their
 * states. Stopped connections stay listed for a while so the panel can show how they ended.
 */
public final class ConnectionFactory {
    private static final Logger LOG = LoggerFactory.getLogger(ConnectionFactory.class);
    private static final int STOPPED_KEPT = 20;

    private final String serverName;
    private final int maxClients;
    private final Function<Socket, Connection> constructor;
    private final int threadPriority;
    private final List<Connection> connections = new ArrayList<>();

    public ConnectionFactory(String serverName, int maxClients, Function<Socket, Connection> constructor) {
        this(serverName, maxClients, constructor, Thread.NORM_PRIORITY);
    }

    /**
     * @param threadPriority the Java priority of each connection's thread: the sender's viewers get the
     *                       maximum, so a short query is not queued behind the receivers and the writer (on
     *                       Linux it takes effect only with {@code -XX:ThreadPriorityPolicy=1}, which
     *                       {@code bin/fdnet} passes when run as root: Java priority 10 becomes nice -5)
     */
    public ConnectionFactory(String serverName, int maxClients, Function<Socket, Connection> constructor,
                             int threadPriority) {
        this.serverName = serverName;
        this.maxClients = maxClients;
        this.constructor = constructor;
        this.threadPriority = threadPriority;
    }

    void accept(Socket socket) {
        synchronized (connections) {
            forgetOldStopped();
            if (active() >= maxClients) {
                LOG.warn("{}: refusing {}: already serving its maximum of {} clients", serverName,
                        socket.getRemoteSocketAddress(), maxClients);
                refuse(socket, "logger " + serverName + " is serving its maximum of " + maxClients + " clients");
                return;
            }
            Connection c = constructor.apply(socket);
            connections.add(c);
            Thread t = new Thread(c, serverName + "-" + socket.getRemoteSocketAddress());
            t.setDaemon(true);
            t.setPriority(threadPriority);
            t.start();
        }
    }

    private int active() {
        int n = 0;
        for (Connection c : connections) {
            if (c.state() != ConnectionState.STOPPED) {
                n++;
            }
        }
        return n;
    }

    private void forgetOldStopped() {
        int stopped = connections.size() - active();
        for (Iterator<Connection> it = connections.iterator(); it.hasNext() && stopped > STOPPED_KEPT; ) {
            if (it.next().state() == ConnectionState.STOPPED) {
                it.remove();
                stopped--;
            }
        }
    }

    private static void refuse(Socket socket, String message) {
        try (socket) {
            OutputStream out = socket.getOutputStream();
            FrameWriter w = new FrameWriter();
            new ErrorFrame(ErrorCode.TOO_MANY_CLIENTS, message).write(w);
            w.writeTo(out);
            out.flush();
        } catch (IOException e) {
            LOG.debug("refusing a client: {}", e.getMessage());
        }
    }

    public List<ClientInfo> clients() {
        synchronized (connections) {
            List<ClientInfo> out = new ArrayList<>(connections.size());
            connections.forEach(c -> out.add(c.info()));
            return out;
        }
    }

    public int activeCount() {
        synchronized (connections) {
            return active();
        }
    }

    void closeAll() {
        List<Connection> all;
        synchronized (connections) {
            all = new ArrayList<>(connections);
        }
        for (Connection c : all) {
            if (c.state() != ConnectionState.STOPPED) {
                c.refuse(ErrorCode.SHUTTING_DOWN, "logger stopping");
            }
        }
    }
}

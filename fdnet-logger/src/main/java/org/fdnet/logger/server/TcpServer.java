package org.fdnet.logger.server;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import org.fdnet.tls.TransportSecurity;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The first layer (thesis, chapter 4 V): only accepts clients and hands each to its factory, so it is
 * quickly available for the next one. Binds to the configured address (127.0.0.1 by default).
 */
public final class TcpServer implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(TcpServer.class);

    private final String name;
    private final ConnectionFactory factory;
    private final ServerSocket serverSocket;
    private final Thread acceptor;
    private volatile boolean closing;

    public TcpServer(String name, String address, int port, ConnectionFactory factory) throws IOException {
        this.name = name;
        this.factory = factory;
        this.serverSocket = TransportSecurity.serverSocket();
        serverSocket.setReuseAddress(true);
        try {
            serverSocket.bind(new InetSocketAddress(InetAddress.getByName(address), port), 200);
        } catch (IOException e) {
            serverSocket.close();
            throw new IOException("cannot listen on " + address + ":" + port + " for the " + name + ": " + e.getMessage(), e);
        }
        this.acceptor = new Thread(this::acceptLoop, name + "-accept");
        acceptor.setDaemon(true);
        acceptor.start();
        LOG.info("{} listening on {}:{}", name, address, port());
    }

    public int port() {
        return serverSocket.getLocalPort();
    }

    public ConnectionFactory factory() {
        return factory;
    }

    private void acceptLoop() {
        while (!closing) {
            try {
                Socket s = serverSocket.accept();
                factory.accept(s);
            } catch (IOException e) {
                if (!closing) {
                    LOG.warn("{}: accept failed: {}", name, e.getMessage());
                }
            }
        }
    }

    @Override
    public void close() {
        closing = true;
        try {
            serverSocket.close();
        } catch (IOException e) {
            LOG.debug("closing {}: {}", name, e.getMessage());
        }
        factory.closeAll();
    }
}

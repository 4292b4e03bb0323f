package org.fdnet.corba;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import org.fdnet.tls.TransportSecurity;

/**
 * JacORB's listening sockets for SSLIOP: TLS with this process's {@link TransportSecurity} identity, every client
 * required to present a certificate of the same network. Named by class in {@link OrbSettings}.
 */
public final class IiopTlsServerSocketFactory implements org.jacorb.orb.factory.ServerSocketFactory {
    private static final int BACKLOG = 50;

    @Override
    public ServerSocket createServerSocket(int port) throws IOException {
        return createServerSocket(port, BACKLOG, null);
    }

    @Override
    public ServerSocket createServerSocket(int port, int backlog) throws IOException {
        return createServerSocket(port, backlog, null);
    }

    @Override
    public ServerSocket createServerSocket(int port, int backlog, InetAddress address) throws IOException {
        TransportSecurity.require("IIOP over TLS on port " + port);
        ServerSocket s = TransportSecurity.serverSocket();
        s.setReuseAddress(true);
        s.bind(new InetSocketAddress(address, port), backlog > 0 ? backlog : BACKLOG);
        return s;
    }
}

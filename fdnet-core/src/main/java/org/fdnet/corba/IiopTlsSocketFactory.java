package org.fdnet.corba;

import java.io.IOException;
import java.net.Socket;
import javax.net.ssl.SSLSocket;
import org.fdnet.tls.TransportSecurity;

/**
 * JacORB's client sockets for SSLIOP, made with this process's {@link TransportSecurity} identity (JacORB's own JSSE
 * factory is bypassed: it reads key stores its own way, and an FDNet process has exactly one identity). Named by
 * class in {@link OrbSettings}; JacORB instantiates it.
 */
public final class IiopTlsSocketFactory implements org.jacorb.orb.factory.SocketFactory {
    private static final int DEFAULT_CONNECT_TIMEOUT_MILLIS = 2_000;

    @Override
    public Socket createSocket(String host, int port) throws IOException {
        return createSocket(host, port, DEFAULT_CONNECT_TIMEOUT_MILLIS);
    }

    @Override
    public Socket createSocket(String host, int port, int timeoutMillis) throws IOException {
        TransportSecurity.require("IIOP over TLS to " + host + ":" + port);
        return TransportSecurity.connect(host, port, timeoutMillis > 0 ? timeoutMillis : DEFAULT_CONNECT_TIMEOUT_MILLIS);
    }

    @Override
    public boolean isSSL(Socket socket) {
        return socket instanceof SSLSocket;
    }
}

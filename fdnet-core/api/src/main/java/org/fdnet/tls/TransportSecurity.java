package org.fdnet.tls;

import java.io.IOException;
import java.net.InetAddress;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.net.UnknownHostException;
import java.util.Optional;
import javax.net.ssl.SSLParameters;
import javax.net.ssl.SSLServerSocket;
import javax.net.ssl.SSLSocket;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Whether this process speaks mutual TLS, and the sockets it makes accordingly.
 *
 * <p>A process has one identity, like JSSE's own default context: the command that starts it calls {@link #use}
 * once (from {@code --tls}), before any ORB or logger connection exists, and every socket FDNet makes afterwards —
 * the ORB's through {@code corba.IiopTlsSocketFactory}, the logger's and its clients' here — follows it. Without a
 * call, every socket is plain TCP, as before.
 */
public final class TransportSecurity {
    private static final Logger LOG = LoggerFactory.getLogger(TransportSecurity.class);
    private static final String[] PROTOCOLS = {"TLSv1.3"};
    private static final Permissions ALLOW_ALL = Permissions.allowAll();
    private static volatile TlsIdentity identity;

    private TransportSecurity() {
    }

    /**
     * Makes every later FDNet connection of this process mutual TLS with {@code tls}.
     *
     * @param tls this process's identity
     */
    public static void use(TlsIdentity tls) {
        identity = tls;
        LOG.info("TLS on: this process is {} ({})", tls.name(), tls.store());
    }

    /** Back to plain TCP (tests that run several processes' roles in one JVM). */
    public static void off() {
        identity = null;
    }

    /**
     * This process's identity.
     *
     * @return the identity given to {@link #use}, or empty while the process speaks plain TCP
     */
    public static Optional<TlsIdentity> current() {
        return Optional.ofNullable(identity);
    }

    /**
     * Who may do what: the network's signed permissions with TLS; without it no certificate names a caller, and
     * everything is allowed, as before permissions existed.
     *
     * @return the grants this process enforces on its callers
     */
    public static Permissions permissions() {
        TlsIdentity tls = identity;
        return tls == null ? ALLOW_ALL : tls.permissions();
    }

    /**
     * Whether this process speaks TLS.
     *
     * @return true after {@link #use}, until {@link #off}
     */
    public static boolean isOn() {
        return identity != null;
    }

    /**
     * Fails unless this process speaks TLS: for the ORB's TLS socket factories, which JacORB may only use then.
     *
     * @param use what needs TLS, for the message
     * @throws IOException naming {@code use}
     */
    public static void require(String use) throws IOException {
        if (!isOn()) {
            throw new IOException(use + " needs TLS, and this process has no TLS identity (--tls)");
        }
    }

    /**
     * A connected client socket (no Nagle delay); with TLS, the handshake is done, so a refused peer fails here and not later.
     *
     * @param host          the server's address
     * @param port          its port
     * @param timeoutMillis how long the connection, and the TLS handshake, may take each, ms
     * @return the socket, without a read timeout
     * @throws IOException when the server cannot be reached or the handshake fails (the socket is closed then)
     */
    public static Socket connect(String host, int port, int timeoutMillis) throws IOException {
        TlsIdentity tls = identity;
        Socket s = tls == null ? new Socket() : tls.context().getSocketFactory().createSocket();
        try {
            s.setTcpNoDelay(true);
            s.connect(new InetSocketAddress(host, port), timeoutMillis);
            if (s instanceof SSLSocket ssl) {
                ssl.setEnabledProtocols(PROTOCOLS);
                ssl.setSoTimeout(timeoutMillis);
                ssl.startHandshake();
                ssl.setSoTimeout(0);
            }
            return s;
        } catch (IOException e) {
            s.close();
            throw e;
        }
    }

    /**
     * An unbound server socket; with TLS, every client must present a certificate the network's CA signed.
     *
     * @return a new socket; the caller binds it
     * @throws IOException when the socket cannot be made
     */
    public static ServerSocket serverSocket() throws IOException {
        TlsIdentity tls = identity;
        if (tls == null) {
            return new ServerSocket();
        }
        SSLServerSocket s = (SSLServerSocket) tls.context().getServerSocketFactory().createServerSocket();
        SSLParameters p = s.getSSLParameters();
        p.setProtocols(PROTOCOLS);
        p.setNeedClientAuth(true);
        s.setSSLParameters(p);
        return s;
    }

    /**
     * Refuses to expose {@code what} on a non-loopback {@code address} without TLS, unless {@code insecure}.
     *
     * @param what     the server, for the message, e.g. {@code the logger's receiver}
     * @param address  the address it is to listen on; a name that does not resolve counts as non-loopback
     * @param insecure {@code --insecure}: allow it without TLS, with a warning in the log
     * @throws IllegalStateException saying what to do
     */
    public static void requireSafeBind(String what, String address, boolean insecure) {
        if (isOn() || insecure || isLoopback(address)) {
            if (!isOn() && !isLoopback(address)) {
                LOG.warn("{} listens on {} WITHOUT TLS (--insecure): anyone who reaches it can read and write", what, address);
            }
            return;
        }
        throw new IllegalStateException(what + " would listen on " + address + ", which is not a loopback address,"
                + " without TLS: anyone who reaches it could read and write the network. Give --tls DIR/NAME.p12"
                + " (make the files with fdnet keys) or, on a network you trust, --insecure");
    }

    static boolean isLoopback(String address) {
        try {
            return InetAddress.getByName(address).isLoopbackAddress();
        } catch (UnknownHostException e) {
            return false;
        }
    }
}

package org.fdnet.tls;

import java.net.Socket;
import java.security.cert.Certificate;
import java.security.cert.X509Certificate;
import javax.naming.InvalidNameException;
import javax.naming.ldap.LdapName;
import javax.naming.ldap.Rdn;
import javax.net.ssl.SSLPeerUnverifiedException;
import javax.net.ssl.SSLSession;
import javax.net.ssl.SSLSocket;

/**
 * The name of the member at the other end of a TLS connection: the CN of the certificate it presented, which
 * {@code fdnet keys NAME} sets to NAME. Kept in the session once found, so a connection's calls read it cheaply.
 */
public final class PeerCertificate {
    private static final String KEY = "org.fdnet.peer-name";

    private PeerCertificate() {
    }

    /**
     * The name of the member at the other end of {@code socket}.
     *
     * @param socket a connected socket
     * @return its certificate's name, or null for a plain socket or a peer without a certificate
     */
    public static String name(Socket socket) {
        return socket instanceof SSLSocket tls ? name(tls.getSession()) : null;
    }

    /**
     * The peer's certificate name.
     *
     * @param session a finished handshake's session
     * @return the CN of the peer's certificate, or null when the peer presented none
     */
    public static String name(SSLSession session) {
        Object known = session.getValue(KEY);
        if (known instanceof String name) {
            return name;
        }
        String name;
        try {
            Certificate[] chain = session.getPeerCertificates();
            name = chain.length > 0 && chain[0] instanceof X509Certificate x ? commonName(x) : null;
        } catch (SSLPeerUnverifiedException e) {
            return null;
        }
        if (name != null) {
            session.putValue(KEY, name);
        }
        return name;
    }

    /**
     * The CN of a certificate's subject.
     *
     * @param certificate a certificate
     * @return its CN, or its whole subject when it has no CN
     */
    public static String commonName(X509Certificate certificate) {
        String subject = certificate.getSubjectX500Principal().getName();
        try {
            for (Rdn rdn : new LdapName(subject).getRdns()) {
                if (rdn.getType().equalsIgnoreCase("CN")) {
                    return rdn.getValue().toString();
                }
            }
        } catch (InvalidNameException e) {
            return subject;
        }
        return subject;
    }
}

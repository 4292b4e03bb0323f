package org.fdnet.tls;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.util.Collections;
import java.util.Objects;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;

/**
 * One process's certificate in a network made by {@code fdnet keys}: {@code NAME.p12} holds its key, its certificate
 * signed by the network's CA and the CA's certificate as the only trusted entry; the store's password is in the file
 * {@code password} beside it.
 *
 * @param store   the PKCS#12 file
 * @param name    the alias of its key entry (the process name it was made for)
 * @param context TLS that presents that key and trusts only the certificates the CA signed
 */
public record TlsIdentity(Path store, String name, SSLContext context) {
    /** The name of the file beside the stores that holds their one password. */
    public static final String PASSWORD_FILE = "password";

    /**
     * Checks the parts.
     *
     * @param store   the PKCS#12 file, not null
     * @param name    the key entry's alias, not null
     * @param context the TLS context, not null
     */
    public TlsIdentity {
        Objects.requireNonNull(store, "store");
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(context, "context");
    }

    /**
     * Loads {@code store} and the {@code password} file beside it.
     *
     * @param store a process's {@code NAME.p12} made by {@code fdnet keys}
     * @return the identity, with a TLS 1.3 context that presents the key and trusts the CA
     * @throws IllegalArgumentException naming the file and what is wrong with it
     */
    public static TlsIdentity load(Path store) {
        Path passwordFile = store.toAbsolutePath().resolveSibling(PASSWORD_FILE);
        if (!Files.isRegularFile(store)) {
            throw new IllegalArgumentException("TLS key store " + store + " does not exist (make one with fdnet keys)");
        }
        char[] password;
        try {
            password = Files.readString(passwordFile, StandardCharsets.UTF_8).strip().toCharArray();
        } catch (IOException e) {
            throw new IllegalArgumentException("cannot read the password of " + store + " from " + passwordFile
                    + ": " + e.getMessage(), e);
        }
        try (InputStream in = Files.newInputStream(store)) {
            KeyStore all = KeyStore.getInstance("PKCS12");
            all.load(in, password);
            KeyStore trusted = KeyStore.getInstance("PKCS12");
            trusted.load(null, null);
            String keyAlias = null;
            for (String alias : Collections.list(all.aliases())) {
                if (all.isCertificateEntry(alias)) {
                    trusted.setCertificateEntry(alias, all.getCertificate(alias));
                } else if (all.isKeyEntry(alias)) {
                    keyAlias = alias;
                }
            }
            if (keyAlias == null || trusted.size() == 0) {
                throw new IllegalArgumentException("TLS key store " + store + " must hold one key and the network's CA"
                        + " certificate (make it with fdnet keys); it holds " + Collections.list(all.aliases()));
            }
            KeyManagerFactory keys = KeyManagerFactory.getInstance("PKIX");
            keys.init(all, password);
            TrustManagerFactory trust = TrustManagerFactory.getInstance("PKIX");
            trust.init(trusted);
            SSLContext context = SSLContext.getInstance("TLSv1.3");
            context.init(keys.getKeyManagers(), trust.getTrustManagers(), null);
            return new TlsIdentity(store, keyAlias, context);
        } catch (IOException | GeneralSecurityException e) {
            throw new IllegalArgumentException("cannot load TLS key store " + store + ": " + e.getMessage(), e);
        }
    }
}

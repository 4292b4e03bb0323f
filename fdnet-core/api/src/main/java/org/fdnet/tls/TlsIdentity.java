package org.fdnet.tls;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.cert.X509Certificate;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Objects;
import javax.net.ssl.KeyManagerFactory;
import javax.net.ssl.SSLContext;
import javax.net.ssl.TrustManagerFactory;

/**
 * One process's certificate in a network made by {@code fdnet keys}: {@code NAME.p12} holds its key, its certificate
 * signed by the network's CA and the CA's certificate as the only trusted entry; the store's password is in the file
 * {@code password} beside it.
 *
 * @param store       the PKCS#12 file
 * @param name        the alias of its key entry (the process name it was made for)
 * @param context     TLS that presents that key and trusts only the certificates the CA signed
 * @param permissions who may do what in the network: its signed {@code permissions} file beside the store
 */
public record TlsIdentity(Path store, String name, SSLContext context, Permissions permissions) {
    /** The name of the file beside the stores that holds their one password. */
    public static final String PASSWORD_FILE = "password";

    /**
     * Checks the parts.
     *
     * @param store   the PKCS#12 file, not null
     * @param name    the key entry's alias, not null
     * @param context the TLS context, not null
     * @param permissions the network's grants, not null
     */
    public TlsIdentity {
        Objects.requireNonNull(store, "store");
        Objects.requireNonNull(name, "name");
        Objects.requireNonNull(context, "context");
        Objects.requireNonNull(permissions, "permissions");
    }

    /**
     * Loads {@code store}, the {@code password} file beside it and the network's {@code permissions}, whose signature
     * must be the CA's ({@link PermissionsFile}).
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
            List<X509Certificate> authorities = new ArrayList<>();
            for (String alias : Collections.list(all.aliases())) {
                if (all.isCertificateEntry(alias)) {
                    trusted.setCertificateEntry(alias, all.getCertificate(alias));
                    if (all.getCertificate(alias) instanceof X509Certificate ca) {
                        authorities.add(ca);
                    }
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
            Permissions permissions = PermissionsFile.load(store.toAbsolutePath().getParent(), authorities);
            return new TlsIdentity(store, keyAlias, context, permissions);
        } catch (IOException | GeneralSecurityException e) {
            throw new IllegalArgumentException("cannot load TLS key store " + store + ": " + e.getMessage(), e);
        }
    }
}

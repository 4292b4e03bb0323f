package org.fdnet.tls;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.security.GeneralSecurityException;
import java.security.PrivateKey;
import java.security.Signature;
import java.security.cert.X509Certificate;
import java.util.Base64;
import java.util.List;

/**
 * A network's permissions file, {@code DIR/permissions}, and its detached signature {@code DIR/permissions.sig}: the
 * CA's key (in {@code ca.p12}) signs the file's bytes (ECDSA with SHA-256, Base64), and every process checks them
 * against the CA certificate its own store already trusts. Nothing else is needed to verify, and only whoever holds
 * the CA's key, who can admit members anyway, can change what members may do.
 */
public final class PermissionsFile {
    /** The file's name beside the key stores. */
    public static final String FILE = "permissions";
    /** Its signature's name. */
    public static final String SIGNATURE = "permissions.sig";
    private static final String ALGORITHM = "SHA256withECDSA";

    private PermissionsFile() {
    }

    /**
     * The permissions of the network whose key files are in {@code dir}, checked against its CA.
     *
     * @param dir     the folder of the key stores
     * @param trusted the CA certificate(s) this process trusts
     * @return the grants
     * @throws IllegalArgumentException one line naming the file and what is wrong: missing, unsigned, not signed by
     *                                  the network's CA (changed since it was signed), or not valid
     */
    public static Permissions load(Path dir, List<X509Certificate> trusted) {
        Path file = dir.resolve(FILE);
        Path signature = dir.resolve(SIGNATURE);
        String resign = "fdnet keys --out " + dir + " --sign-permissions";
        if (!Files.isRegularFile(file)) {
            throw new IllegalArgumentException("permissions file " + file + " is missing: every process of a TLS network"
                    + " needs it (fdnet keys --out " + dir + " writes the default, which allows everything)");
        }
        if (!Files.isRegularFile(signature)) {
            throw new IllegalArgumentException("permissions file " + file + " is not signed: " + signature
                    + " is missing (sign it with " + resign + ")");
        }
        byte[] bytes;
        byte[] signed;
        try {
            bytes = Files.readAllBytes(file);
            signed = Base64.getMimeDecoder().decode(Files.readString(signature, StandardCharsets.US_ASCII).strip());
        } catch (IOException | IllegalArgumentException e) {
            throw new IllegalArgumentException("permissions file " + file + " or its signature cannot be read: "
                    + e.getMessage(), e);
        }
        if (!signedByAny(bytes, signed, trusted)) {
            throw new IllegalArgumentException("permissions file " + file + " does not match its signature " + signature
                    + " by this network's CA: it was changed after signing, or signed by another CA (whoever holds"
                    + " ca.p12 signs it again with " + resign + ")");
        }
        return Permissions.parse(new String(bytes, StandardCharsets.UTF_8), file.toString());
    }

    /**
     * Writes the default file (every member may do everything) and its signature, unless a file is there already.
     *
     * @param dir   the folder of the key stores
     * @param caKey the CA's private key
     * @return whether the default was written
     * @throws IOException when a file cannot be written
     */
    public static boolean writeDefault(Path dir, PrivateKey caKey) throws IOException {
        Path file = dir.resolve(FILE);
        if (Files.exists(file)) {
            return false;
        }
        Files.writeString(file, Permissions.ALLOW_ALL_TEXT, StandardCharsets.UTF_8);
        sign(dir, caKey);
        return true;
    }

    /**
     * Checks the file and signs it with the CA's key (after it was edited).
     *
     * @param dir   the folder of the key stores
     * @param caKey the CA's private key
     * @return the signature file
     * @throws IOException              when a file cannot be read or written
     * @throws IllegalArgumentException when the file is not valid ({@code FILE:LINE: what}); nothing is signed then
     */
    public static Path sign(Path dir, PrivateKey caKey) throws IOException {
        Path file = dir.resolve(FILE);
        byte[] bytes = Files.readAllBytes(file);
        Permissions.parse(new String(bytes, StandardCharsets.UTF_8), file.toString());
        try {
            Signature s = Signature.getInstance(ALGORITHM);
            s.initSign(caKey);
            s.update(bytes);
            Path signature = dir.resolve(SIGNATURE);
            Files.writeString(signature, Base64.getMimeEncoder().encodeToString(s.sign()) + "\n",
                    StandardCharsets.US_ASCII);
            return signature;
        } catch (GeneralSecurityException e) {
            throw new IOException("cannot sign " + file + " with the CA's key: " + e.getMessage(), e);
        }
    }

    private static boolean signedByAny(byte[] bytes, byte[] signed, List<X509Certificate> trusted) {
        for (X509Certificate ca : trusted) {
            try {
                Signature s = Signature.getInstance(ALGORITHM);
                s.initVerify(ca.getPublicKey());
                s.update(bytes);
                if (s.verify(signed)) {
                    return true;
                }
            } catch (GeneralSecurityException e) {
                // a signature that does not even parse for this key: not signed by it
            }
        }
        return false;
    }
}

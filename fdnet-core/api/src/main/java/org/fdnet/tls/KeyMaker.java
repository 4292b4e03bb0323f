package org.fdnet.tls;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.GeneralSecurityException;
import java.security.KeyStore;
import java.security.PrivateKey;
import java.security.SecureRandom;
import java.util.ArrayList;
import java.util.HexFormat;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.regex.Pattern;

/**
 * Makes a network's CA and one certificate per process with the JDK's {@code keytool} (no library, nothing
 * downloaded): EC P-256 keys, certificates valid for both ends of a connection, ten years.
 *
 * <p>Files: {@code ca.p12} (the CA's key: whoever holds it can admit new processes, so keep it off the robots),
 * {@code NAME.p12} per process (its key, its certificate, the CA certificate as trusted entry), {@code password}.
 * {@code permissions} (with {@code permissions.sig}, the CA's signature) says who may do what ({@link Permissions}); its
 * default allows everything to every member. Existing files are kept: running it again with new names adds processes
 * to the same network.
 */
public final class KeyMaker {
    private static final Pattern NAME = Pattern.compile("[A-Za-z0-9][A-Za-z0-9._-]*");
    private static final String CA = "ca";
    private static final String CA_ALIAS = "fdnet-ca";
    private static final long TOOL_TIMEOUT_SECONDS = 120;
    private static final String PASSWORD_VARIABLE = "FDNET_KEYS_PASSWORD";

    private final Path dir;
    private final Path keytool;

    /**
     * A maker for the network whose key files live in {@code dir}.
     *
     * @param dir the folder of the network's key files, made when missing
     */
    public KeyMaker(Path dir) {
        this.dir = dir.toAbsolutePath();
        this.keytool = Path.of(System.getProperty("java.home"), "bin", "keytool");
    }

    /**
     * The CA (made once), then a store for each of {@code names} that does not have one yet; returns the files made.
     *
     * @param names process names: letters, digits, '.', '_' or '-', not {@code ca}
     * @return the key stores made now, the CA's first when it was made; empty when every file existed
     * @throws IllegalArgumentException when a name is not allowed
     * @throws IOException              when a file cannot be written or made owner-only, or keytool fails (its output
     *                                  is in the message)
     * @throws InterruptedException     when interrupted while keytool runs
     */
    public List<Path> make(List<String> names) throws IOException, InterruptedException {
        for (String n : names) {
            if (!NAME.matcher(n).matches() || n.equals(CA)) {
                throw new IllegalArgumentException("process name '" + n + "' must be letters, digits, '.', '_' or '-'"
                        + " and not 'ca'");
            }
        }
        Files.createDirectories(dir);
        String password = password();
        List<Path> made = new ArrayList<>();
        Path caStore = dir.resolve(CA + ".p12");
        Path caPem = dir.resolve(CA + ".pem");
        if (!Files.exists(caStore)) {
            keytool(password, "-genkeypair", "-alias", CA_ALIAS, "-keyalg", "EC", "-groupname", "secp256r1",
                    "-dname", "CN=FDNet network CA", "-ext", "bc:c", "-validity", "3650",
                    "-keystore", caStore.toString(), "-storetype", "PKCS12");
            ownerOnly(caStore);
            made.add(caStore);
        }
        if (!Files.exists(caPem)) {
            keytool(password, "-exportcert", "-rfc", "-alias", CA_ALIAS, "-keystore", caStore.toString(),
                    "-file", caPem.toString());
        }
        if (PermissionsFile.writeDefault(dir, caKey(caStore, password))) {
            made.add(dir.resolve(PermissionsFile.FILE));
        }
        ExecutorService pool = Executors.newFixedThreadPool(Math.max(1, Runtime.getRuntime().availableProcessors()));
        try {
            List<Future<Path>> jobs = new ArrayList<>();
            for (String n : names) {
                if (!Files.exists(store(n))) {
                    jobs.add(pool.submit(() -> makeProcess(n, password, caStore, caPem)));
                }
            }
            for (Future<Path> job : jobs) {
                made.add(job.get());
            }
        } catch (ExecutionException e) {
            Throwable cause = e.getCause();
            throw cause instanceof IOException io ? io : new IOException(cause.getMessage(), cause);
        } finally {
            pool.shutdownNow();
        }
        return made;
    }

    /**
     * Signs the network's {@code permissions} file again with the CA's key, after it was edited.
     *
     * @return the signature file
     * @throws IOException              when the CA's store, the password or the file cannot be read, or the signature
     *                                  cannot be written
     * @throws IllegalArgumentException when the file is not valid ({@code FILE:LINE: what}); nothing is signed then
     */
    public Path signPermissions() throws IOException {
        Path caStore = dir.resolve(CA + ".p12");
        if (!Files.isRegularFile(caStore)) {
            throw new IOException("cannot sign " + dir.resolve(PermissionsFile.FILE) + ": the CA's store " + caStore
                    + " is not here (sign where the network's keys were made)");
        }
        if (!Files.isRegularFile(dir.resolve(PermissionsFile.FILE))) {
            throw new IOException("cannot sign " + dir.resolve(PermissionsFile.FILE) + ": there is no such file");
        }
        return PermissionsFile.sign(dir, caKey(caStore, password()));
    }

    private static PrivateKey caKey(Path caStore, String password) throws IOException {
        try (InputStream in = Files.newInputStream(caStore)) {
            KeyStore ks = KeyStore.getInstance("PKCS12");
            ks.load(in, password.toCharArray());
            if (ks.getKey(CA_ALIAS, password.toCharArray()) instanceof PrivateKey key) {
                return key;
            }
            throw new IOException(caStore + " holds no CA key '" + CA_ALIAS + "'");
        } catch (GeneralSecurityException e) {
            throw new IOException("cannot read the CA's key from " + caStore + ": " + e.getMessage(), e);
        }
    }

    /**
     * Deletes the folder with every key file in it: for throwaway networks (benchmarks).
     *
     * @throws IOException when a file cannot be deleted
     */
    public void deleteAll() throws IOException {
        if (!Files.isDirectory(dir)) {
            return;
        }
        try (var files = Files.list(dir)) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Files.delete(f);
            }
        }
        Files.delete(dir);
    }

    /**
     * Where a process's key store is, made or not.
     *
     * @param name the process name
     * @return {@code NAME.p12} in the folder
     */
    public Path store(String name) {
        return dir.resolve(name + ".p12");
    }

    private Path makeProcess(String name, String password, Path caStore, Path caPem)
            throws IOException, InterruptedException {
        Path building = dir.resolve(name + ".p12.part");
        Path csr = dir.resolve(name + ".csr");
        Path pem = dir.resolve(name + ".pem");
        Files.deleteIfExists(building);
        keytool(password, "-genkeypair", "-alias", name, "-keyalg", "EC", "-groupname", "secp256r1",
                "-dname", "CN=" + name, "-validity", "3650", "-keystore", building.toString(), "-storetype", "PKCS12");
        keytool(password, "-certreq", "-alias", name, "-keystore", building.toString(), "-file", csr.toString());
        keytool(password, "-gencert", "-rfc", "-alias", CA_ALIAS, "-keystore", caStore.toString(),
                "-infile", csr.toString(), "-outfile", pem.toString(), "-validity", "3650",
                "-ext", "ku:c=digitalSignature", "-ext", "eku=serverAuth,clientAuth");
        keytool(password, "-importcert", "-noprompt", "-alias", CA_ALIAS, "-file", caPem.toString(),
                "-keystore", building.toString());
        keytool(password, "-importcert", "-alias", name, "-file", pem.toString(), "-keystore", building.toString());
        Files.delete(csr);
        Files.delete(pem);
        Path store = store(name);
        Files.move(building, store);
        ownerOnly(store);
        return store;
    }

    /** The network's one password, made on first use and readable by its owner only. */
    private String password() throws IOException {
        Path file = dir.resolve(TlsIdentity.PASSWORD_FILE);
        if (Files.exists(file)) {
            return Files.readString(file, StandardCharsets.UTF_8).strip();
        }
        byte[] random = new byte[18];
        new SecureRandom().nextBytes(random);
        String password = HexFormat.of().formatHex(random);
        Files.writeString(file, password + "\n", StandardCharsets.UTF_8);
        ownerOnly(file);
        return password;
    }

    /** Keys and the password are readable by their owner only. */
    private static void ownerOnly(Path file) throws IOException {
        try {
            Files.setPosixFilePermissions(file, PosixFilePermissions.fromString("rw-------"));
        } catch (UnsupportedOperationException e) {
            throw new IOException("cannot make " + file + " readable by its owner only on this file system", e);
        }
    }

    private void keytool(String password, String... args) throws IOException, InterruptedException {
        List<String> command = new ArrayList<>(List.of(keytool.toString(), "-J-XX:TieredStopAtLevel=1",
                "-J-XX:+UseSerialGC"));
        command.addAll(List.of(args));
        command.addAll(List.of("-storepass:env", PASSWORD_VARIABLE));
        if (args[0].equals("-genkeypair")) {
            command.addAll(List.of("-keypass:env", PASSWORD_VARIABLE));
        }
        ProcessBuilder pb = new ProcessBuilder(command).redirectErrorStream(true);
        pb.environment().put(PASSWORD_VARIABLE, password);
        Process p = pb.start();
        String output = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!p.waitFor(TOOL_TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new IOException("keytool " + args[0] + " did not finish in " + TOOL_TIMEOUT_SECONDS + " s");
        }
        if (p.exitValue() != 0) {
            throw new IOException("keytool " + String.join(" ", args) + " failed: " + output.strip());
        }
    }
}

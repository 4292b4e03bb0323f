package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.security.KeyStore;
import java.security.PrivateKey;
import java.security.cert.Certificate;
import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fdnet.corba.idl.Host;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.tls.TestKeys;
import org.fdnet.tls.TlsIdentity;
import org.fdnet.tls.TransportSecurity;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A member written in C++ on omniORB, not JacORB, over SSLIOP with its own certificate: limited to reading, it reads a
 * Data on a host and is refused the write with the reason (certificate, Data, right), and nothing is written; a
 * certificate allowed to write that Data writes it with the same client. The client ({@code src/test/cpp}) is compiled
 * here against the stubs omniidl makes from {@code idl/fdnet.idl}, all in {@code target/omniorb}; its key and
 * certificate are exported from its {@code NAME.p12} to PEM, as omniORB's sslTP reads them.
 */
@Timeout(value = 240, unit = TimeUnit.SECONDS)
class OmniOrbMemberTest {
    private static final String GRANTS = PermissionsAcrossProcessesTest.OPERATOR_DOES_EVERYTHING + """
            member    write    main/Certainty
            """;
    private static final NodeRef CERTAINTY = new NodeRef("main", "Certainty");
    private static final Path WORK = Path.of("target", "omniorb").toAbsolutePath();
    private static final Path IDL = Path.of("..", "idl", "fdnet.idl").toAbsolutePath().normalize();
    private static final Path CLIENT_SOURCE = Path.of("src", "test", "cpp", "member_client.cc").toAbsolutePath();
    private static final long TOOL_TIMEOUT_SECONDS = 180;
    private final List<AutoCloseable> toClose = new ArrayList<>();

    @AfterEach
    void stop() throws Exception {
        for (int i = toClose.size() - 1; i >= 0; i--) {
            toClose.get(i).close();
        }
        TransportSecurity.off();
    }

    @Test
    void shouldRefuseAWriteFromAnOmniOrbClientWhoseCertificateMayOnlyRead() throws Exception {
        Path client = compileClient();
        Path keys = TestKeys.withPermissions("permissions-omniorb", GRANTS,
                List.of("naming", "crawler", "operator", "reader", "member"));
        int port = FdnetChildProcess.freePort();
        String naming = "corbaloc::127.0.0.1:" + port + "/NameService";
        toClose.add(FdnetChildProcess.start("naming", List.of("naming", "--port", Integer.toString(port), "--tls",
                keys.resolve("naming.p12").toString()), "fdnet naming ready", 60_000));
        toClose.add(FdnetChildProcess.start("crawler", List.of("host", "--name", "crawler", "--naming", naming, "--tls",
                keys.resolve("crawler.p12").toString()), "fdnet host crawler ready", 60_000));
        TransportSecurity.use(TlsIdentity.load(keys.resolve("operator.p12")));
        OrbRuntime orb = OrbRuntime.start(OrbSettings.defaults().withNaming(naming).withCallTimeoutMillis(10_000));
        toClose.add(orb);
        Host crawler = HostDirectory.connect(orb).find("crawler").orElseThrow();
        crawler.createNode(IdlMapping.spec("main", NodeInfo.data("Certainty", "DoubleData")));
        crawler.write(IdlMapping.id(CERTAINTY), ValueCodec.encode(0.25));
        Path ior = WORK.resolve("crawler.ior");
        Files.writeString(ior, orb.orb().object_to_string(crawler) + "\n", StandardCharsets.US_ASCII);

        Run reader = run(client, ior, keys, "reader");
        assertThat(reader.output).contains("read main/Certainty = 0.25")
                .contains("refused: NO_PERMISSION: certificate 'reader' may not write main/Certainty");
        assertThat(reader.exit).as(reader.output).isEqualTo(3);
        assertThat(ValueCodec.decode(crawler.read(IdlMapping.id(CERTAINTY)))).as("nothing written").isEqualTo(0.25);

        Run member = run(client, ior, keys, "member");
        assertThat(member.output).as("the same client with a certificate that may write").contains("written");
        assertThat(member.exit).as(member.output).isZero();
        assertThat(ValueCodec.decode(crawler.read(IdlMapping.id(CERTAINTY)))).isEqualTo(1.25);
    }

    private record Run(int exit, String output) {
    }

    private static Run run(Path client, Path ior, Path keys, String name) throws Exception {
        Path pem = exportKeyAndCertificate(keys, name);
        return tool("member_client-" + name, List.of(client.toString(), ior.toString(), "main", "Certainty",
                keys.resolve("ca.pem").toString(), pem.toString()));
    }

    /** The stubs of fdnet.idl (omniidl) and the client, compiled with g++ against omniORB and its SSL transport. */
    private static Path compileClient() throws Exception {
        Files.createDirectories(WORK);
        for (String tool : List.of("omniidl", "g++")) {
            Run found = tool(List.of("sh", "-c", "command -v " + tool));
            assertThat(found.exit).as("the omniORB client test needs " + tool + ": apt-get install -y omniorb omniidl"
                    + " libomniorb4-dev g++ (.ci/run installs them)").isZero();
        }
        Run stubs = tool(List.of("omniidl", "-bcxx", "-Wbh=.hh", "-Wbs=SK.cc", "-C", WORK.toString(), IDL.toString()));
        assertThat(stubs.exit).as("omniidl: " + stubs.output).isZero();
        Path client = WORK.resolve("member_client");
        Run gcc = tool(List.of("g++", "-O1", "-std=c++17", "-I", WORK.toString(), "-o", client.toString(),
                CLIENT_SOURCE.toString(), WORK.resolve("fdnetSK.cc").toString(),
                "-lomniORB4", "-lomnithread", "-lomnisslTP4", "-lssl", "-lcrypto"));
        assertThat(gcc.exit).as("g++: " + gcc.output).isZero();
        return client;
    }

    /** NAME's certificate chain and private key from {@code NAME.p12}, PEM in one owner-only file. */
    private static Path exportKeyAndCertificate(Path keys, String name) throws Exception {
        char[] password = Files.readString(keys.resolve("password")).strip().toCharArray();
        KeyStore store = KeyStore.getInstance("PKCS12");
        try (InputStream in = Files.newInputStream(keys.resolve(name + ".p12"))) {
            store.load(in, password);
        }
        StringBuilder pem = new StringBuilder();
        for (Certificate c : store.getCertificateChain(name)) {
            pem.append(block("CERTIFICATE", c.getEncoded()));
        }
        pem.append(block("PRIVATE KEY", ((PrivateKey) store.getKey(name, password)).getEncoded()));
        Path file = WORK.resolve(name + ".pem");
        Files.deleteIfExists(file);
        Files.createFile(file, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rw-------")));
        Files.writeString(file, pem, StandardCharsets.US_ASCII);
        return file;
    }

    private static String block(String type, byte[] der) {
        return "-----BEGIN " + type + "-----\n"
                + Base64.getMimeEncoder(64, "\n".getBytes(StandardCharsets.US_ASCII)).encodeToString(der)
                + "\n-----END " + type + "-----\n";
    }

    private static Run tool(List<String> command) throws IOException, InterruptedException {
        return tool(Path.of(command.get(0)).getFileName().toString(), command);
    }

    /** Runs a program to its end (bounded); its output is kept in {@code target/omniorb/LABEL.out}. */
    private static Run tool(String label, List<String> command) throws IOException, InterruptedException {
        Path log = WORK.resolve(label + ".out");
        Process p = new ProcessBuilder(command).redirectErrorStream(true).redirectOutput(log.toFile()).start();
        try {
            if (!p.waitFor(TOOL_TIMEOUT_SECONDS, TimeUnit.SECONDS)) {
                throw new AssertionError(command.get(0) + " did not finish in " + TOOL_TIMEOUT_SECONDS + " s: "
                        + Files.readString(log));
            }
            return new Run(p.exitValue(), Files.readString(log));
        } finally {
            p.destroyForcibly();
        }
    }
}

package org.fdnet.logger;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.Socket;
import java.nio.file.Path;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import javax.net.ssl.SSLException;
import javax.net.ssl.SSLSocket;
import org.fdnet.cli.FdnetCommand;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.event.client.ViewerClient;
import org.fdnet.event.wire.ErrorFrame;
import org.fdnet.event.wire.Frame;
import org.fdnet.event.wire.FrameReader;
import org.fdnet.event.wire.FrameWriter;
import org.fdnet.event.wire.MessageType;
import org.fdnet.event.wire.Hello;
import org.fdnet.tls.TestKeys;
import org.fdnet.tls.TlsIdentity;
import org.fdnet.tls.TransportSecurity;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * The logger with mutual TLS: a raw TCP client and a client with another network's certificate are refused on both
 * ports before the logger reads a frame, and store nothing; a core and a viewer with the network's certificate work.
 * A core whose certificate the network's permissions do not let record is refused at its HELLO with the reason. Off
 * loopback, the logger, a host and the naming service refuse to start without TLS unless told --insecure.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class LoggerTlsTest {
    @TempDir
    static Path folder;
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    @AfterEach
    void plainAgain() {
        TransportSecurity.off();
    }

    @Test
    void shouldStoreOnlyWhatClientsWithTheNetworksCertificateSend() throws Exception {
        TransportSecurity.use(TlsIdentity.load(TestKeys.network("logger")));
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig())) {
            logger.start();
            TlsIdentity foreign = TlsIdentity.load(TestKeys.foreign());
            for (int port : new int[] {logger.receiverPort(), logger.senderPort()}) {
                assertThat(plainHelloIsAnswered(port)).as("raw TCP on port " + port).isFalse();
                assertThatThrownBy(() -> handshake(foreign, port)).as("another network on port " + port)
                        .isInstanceOf(SSLException.class);
            }
            try (LoggerClient member = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(),
                    "tls-core").withJournal(folder.resolve("j"), 16 << 20))) {
                Producer producer = new Producer(new TestEvents(4), member, 10);
                Thread.sleep(300);
                long produced = producer.stop();
                assertThat(member.flush(60_000)).isTrue();
                long stored = database.fixture().count("SELECT count(*) FROM datavalue_log")
                        + database.fixture().count("SELECT count(*) FROM procvalue_log")
                        + database.fixture().count("SELECT count(*) FROM netcommand_log");
                assertThat(stored).as("only the member's events").isEqualTo(produced).isPositive();
                try (ViewerClient viewer = new ViewerClient("127.0.0.1", logger.senderPort(), "tls-viewer", e -> { })) {
                    assertThat(viewer.nodes("")).isNotEmpty();
                }
            }
        }
    }

    @Test
    void shouldRefuseAtTheHelloACoreWhoseCertificateMayNotRecord() throws Exception {
        Path keys = TestKeys.withPermissions("permissions-record", "*  read  *\nlogger  record\ncore  record\n",
                List.of("logger", "core", "viewer"));
        TransportSecurity.use(TlsIdentity.load(keys.resolve("logger.p12")));
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig())) {
            logger.start();
            Frame refused = helloAs(TlsIdentity.load(keys.resolve("viewer.p12")), logger.receiverPort());
            assertThat(refused.type()).isEqualTo(MessageType.ERROR);
            assertThat(ErrorFrame.read(refused).message()).contains("certificate 'viewer' may not record");
            Frame welcomed = helloAs(TlsIdentity.load(keys.resolve("core.p12")), logger.receiverPort());
            assertThat(welcomed.type()).as("a certificate allowed to record").isEqualTo(MessageType.WELCOME);
        }
    }

    @Test
    void shouldRefuseToListenOffLoopbackWithoutTlsUnlessInsecure() {
        String elsewhere = "192.0.2.7"; // TEST-NET-1: checked before anything binds, so it need not be this machine's
        for (String[] command : new String[][] {{"logger", "--bind", elsewhere}, {"naming", "--bind", elsewhere},
                {"host", "--name", "x", "--bind", elsewhere}, {"run", "../../networks/two-robots.fdn", "--bind", elsewhere}}) {
            StringWriter err = new StringWriter();
            CommandLine cli = FdnetCommand.commandLine().setErr(new PrintWriter(err, true));
            int exit = cli.execute(command);
            assertThat(exit).as(String.join(" ", command)).isNotZero();
            assertThat(err.toString()).as(String.join(" ", command)).contains(elsewhere).contains("without TLS")
                    .contains("--insecure");
        }
    }

    /** Sends a well-formed HELLO without TLS; whether the logger answers anything before it closes. */
    private static boolean plainHelloIsAnswered(int port) throws IOException {
        try (Socket s = new Socket("127.0.0.1", port)) {
            s.setSoTimeout(10_000);
            OutputStream out = s.getOutputStream();
            FrameWriter w = new FrameWriter();
            Hello.core(UUID.randomUUID(), "raw-tcp").write(w);
            w.writeTo(out);
            out.flush();
            InputStream in = s.getInputStream();
            try {
                int first = in.read();
                // a TLS server answers a non-TLS first record with at most an alert record (type 21), never a frame
                return first != -1 && first != 21;
            } catch (IOException closed) {
                return false;
            }
        }
    }

    /** Sends a core's HELLO over TLS as {@code identity}; the logger's first answer. */
    private static Frame helloAs(TlsIdentity identity, int port) throws IOException {
        try (SSLSocket s = (SSLSocket) identity.context().getSocketFactory().createSocket("127.0.0.1", port)) {
            s.setSoTimeout(10_000);
            FrameWriter w = new FrameWriter();
            Hello.core(UUID.randomUUID(), "core-" + identity.name()).write(w);
            w.writeTo(s.getOutputStream());
            s.getOutputStream().flush();
            Frame answer = new FrameReader(s.getInputStream(), 1 << 20).read();
            assertThat(answer).as("an answer to the HELLO").isNotNull();
            return answer;
        }
    }

    private static void handshake(TlsIdentity identity, int port) throws IOException {
        try (SSLSocket s = (SSLSocket) identity.context().getSocketFactory().createSocket("127.0.0.1", port)) {
            s.setSoTimeout(10_000);
            s.startHandshake();
            // TLS 1.3: the server checks the client's certificate after the client's handshake is done; the
            // refusal arrives with the first read.
            s.getOutputStream().write(0);
            s.getOutputStream().flush();
            s.getInputStream().read();
        }
    }
}

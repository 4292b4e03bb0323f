package org.fdnet.logger;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.DataInputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.event.wire.FrameWriter;
import org.fdnet.event.wire.Hello;
import org.fdnet.event.wire.MessageType;
import org.fdnet.event.wire.Protocol;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.logger.server.ClientInfo;
import org.fdnet.logger.server.ConnectionState;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

/**
 * Garbage, truncated and oversized frames, and a peer of another protocol version, close their own connection only; good clients never notice. One client
 * beyond {@code receiver.maxClients} / {@code sender.maxClients} is refused with an ERROR naming the limit, while
 * the ones served stay served; once one leaves, a new one is taken.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class ProtocolAbuseTest {
    @TempDir
    static Path folder;
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    @Test
    void shouldCloseOnlyTheOffendingConnectionsAndKeepEveryAcceptedEvent() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig())) {
            logger.start();
            int port = logger.receiverPort();
            try (LoggerClient good = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", port, "good-core")
                    .withJournal(folder.resolve("j"), 16 << 20))) {
                Producer producer = new Producer(new TestEvents(4), good, 10);

                String garbage = closedWithError(port, out -> out.write("GET / HTTP/1.1\r\nHost: x\r\n\r\n"
                        .getBytes(StandardCharsets.US_ASCII)));
                assertThat(garbage).contains("frame length");

                String oversized = closedWithError(port, out -> {
                    hello(out);
                    new DataOutputStream(out).writeInt(64 << 20);
                });
                assertThat(oversized).contains("outside 1..");

                String malformed = closedWithError(port, out -> {
                    hello(out);
                    FrameWriter w = new FrameWriter();
                    w.begin(MessageType.EVENTS).putLong(1).putInt(3).putByte(1).putInt(0); // count 3, then cut short
                    w.writeTo(out);
                });
                assertThat(malformed).contains("malformed EVENTS frame");

                String wrongFirst = closedWithError(port, out -> {
                    FrameWriter w = new FrameWriter();
                    w.begin(MessageType.ACK).putLong(5);
                    w.writeTo(out);
                });
                assertThat(wrongFirst).contains("expected HELLO");

                String versionOne = closedWithError(port, out -> { // a core of the text-value protocol
                    FrameWriter w = new FrameWriter();
                    new Hello(1, Protocol.ROLE_CORE, UUID.randomUUID(), "old-core").write(w);
                    w.writeTo(out);
                });
                assertThat(versionOne).contains("protocol version 1 not supported").contains("version " + Protocol.VERSION);

                truncatedThenGone(port);

                Thread.sleep(500);
                long produced = producer.stop();
                assertThat(good.flush(60_000)).isTrue();
                assertThat(good.status().connected()).isTrue();
                long stored = database.fixture().count("SELECT count(*) FROM datavalue_log") + database.fixture().count("SELECT count(*) FROM procvalue_log")
                        + database.fixture().count("SELECT count(*) FROM netcommand_log");
                assertThat(stored).isEqualTo(produced);
                assertThat(logger.status().cores()).filteredOn(c -> c.state() == ConnectionState.STOPPED)
                        .hasSizeGreaterThanOrEqualTo(5).extracting(ClientInfo::endReason).allMatch(r -> !r.isEmpty());
            }
        }
    }

    private interface Abuse {
        void send(OutputStream out) throws IOException;
    }

    private static void hello(OutputStream out) throws IOException {
        FrameWriter w = new FrameWriter();
        Hello.core(UUID.randomUUID(), "abuser").write(w);
        w.writeTo(out);
    }

    /** Sends the abuse and returns the ERROR message the logger answers before it closes. */
    private static String closedWithError(int port, Abuse abuse) throws IOException {
        try (Socket s = new Socket("127.0.0.1", port)) {
            s.setSoTimeout(10_000);
            abuse.send(s.getOutputStream());
            s.getOutputStream().flush();
            DataInputStream in = new DataInputStream(s.getInputStream());
            while (true) {
                int length = in.readInt();
                int type = in.readUnsignedByte();
                byte[] payload = new byte[length - 1];
                in.readFully(payload);
                if (type == MessageType.ERROR.code()) {
                    String message = new String(payload, 6, payload.length - 6, StandardCharsets.UTF_8);
                    assertThat(in.read()).as("connection closed after ERROR").isEqualTo(-1);
                    return message;
                }
            }
        }
    }

    private static void truncatedThenGone(int port) throws IOException {
        try (Socket s = new Socket("127.0.0.1", port)) {
            OutputStream out = s.getOutputStream();
            hello(out);
            new DataOutputStream(out).writeInt(1000);
            out.write(new byte[] {(byte) MessageType.EVENTS.code(), 0, 0});
            out.flush();
        }
    }

    @Test
    void shouldRefuseTheClientBeyondEachServersMaximumAndTakeANewOneWhenOneLeaves() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig()
                .set(LoggerSetting.RECEIVER_MAX_CLIENTS, "2").set(LoggerSetting.SENDER_MAX_CLIENTS, "1"))) {
            logger.start();
            keepsToTheMaximum(logger.receiverPort(), 2, () -> logger.status().cores(),
                    out -> sendHello(out, Hello.core(UUID.randomUUID(), "core")), "receiver");
            keepsToTheMaximum(logger.senderPort(), 1, () -> logger.status().viewers(),
                    out -> sendHello(out, Hello.viewer("viewer")), "sender");
        }
    }

    private static void keepsToTheMaximum(int port, int max, Supplier<List<ClientInfo>> clients,
                                               Abuse hello, String server) throws Exception {
        Socket[] served = new Socket[max];
        try {
            for (int i = 0; i < max; i++) {
                served[i] = new Socket("127.0.0.1", port);
                hello.send(served[i].getOutputStream());
            }
            awaitActive(clients, max);
            String refused = closedWithError(port, hello);
            assertThat(refused).isEqualTo("logger " + server + " is serving its maximum of " + max + " clients");
            assertThat(active(clients)).as("the served ones are still served").isEqualTo(max);

            served[0].close();
            awaitActive(clients, max - 1);
            try (Socket next = new Socket("127.0.0.1", port)) {
                hello.send(next.getOutputStream());
                awaitActive(clients, max);
            }
        } finally {
            for (Socket s : served) {
                if (s != null) {
                    s.close();
                }
            }
        }
    }

    private static void sendHello(OutputStream out, Hello hello) throws IOException {
        FrameWriter w = new FrameWriter();
        hello.write(w);
        w.writeTo(out);
        out.flush();
    }

    private static long active(Supplier<List<ClientInfo>> clients) {
        return clients.get().stream().filter(c -> c.state() != ConnectionState.STOPPED).count();
    }

    private static void awaitActive(Supplier<List<ClientInfo>> clients, int n) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (active(clients) != n) {
            assertThat(System.nanoTime()).as("%d clients served: %s", n, clients.get()).isLessThan(deadline);
            Thread.sleep(20);
        }
    }
}

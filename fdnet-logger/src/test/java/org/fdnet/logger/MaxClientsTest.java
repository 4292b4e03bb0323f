package org.fdnet.logger;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import org.fdnet.event.wire.FrameWriter;
import org.fdnet.event.wire.Hello;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.logger.server.ClientInfo;
import org.fdnet.logger.server.ConnectionState;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * {@code receiver.maxClients} and {@code sender.maxClients}: one client more than the maximum is refused with
 * an ERROR naming the limit, while the ones served keep being served; once one leaves, a new one is taken.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class MaxClientsTest {
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    @Test
    void shouldRefuseTheClientBeyondEachServersMaximumAndTakeANewOneWhenOneLeaves() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig()
                .set(LoggerSetting.RECEIVER_MAX_CLIENTS, "2").set(LoggerSetting.SENDER_MAX_CLIENTS, "1"))) {
            logger.start();
            shouldKeepToTheMaximum(logger.receiverPort(), 2, () -> logger.status().cores(),
                    out -> send(out, Hello.core(UUID.randomUUID(), "core")), "receiver");
            shouldKeepToTheMaximum(logger.senderPort(), 1, () -> logger.status().viewers(),
                    out -> send(out, Hello.viewer("viewer")), "sender");
        }
    }

    private static void shouldKeepToTheMaximum(int port, int max, Supplier<List<ClientInfo>> clients,
                                               ProtocolAbuseTest.Abuse hello, String server) throws Exception {
        Socket[] served = new Socket[max];
        try {
            for (int i = 0; i < max; i++) {
                served[i] = new Socket("127.0.0.1", port);
                hello.send(served[i].getOutputStream());
            }
            awaitActive(clients, max);
            String refused = ProtocolAbuseTest.closedWithError(port, hello);
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

    private static void send(OutputStream out, Hello hello) throws IOException {
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

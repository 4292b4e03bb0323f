package org.fdnet.event.client;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.net.ServerSocket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.ValueType;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

@Timeout(60)
class LoggerClientTest {
    @TempDir
    Path folder;

    private static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    private static List<NetworkEvent> events(int n) {
        List<NetworkEvent> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            out.add(new DataValueEvent(i % 7, 1000 + i, ValueType.LONG, Integer.toString(i)));
        }
        return out;
    }

    @Test
    void shouldSpillToTheJournalWhileTheLoggerIsAwayAndDeliverEverythingInOrderOnceItComes() throws Exception {
        int port = freePort();
        Path journal = folder.resolve("journal");
        List<NetworkEvent> sent = events(50_000);
        try (LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", port, "core")
                .withMemoryEvents(1000).withJournal(journal, 64 << 20))) {
            long t0 = System.nanoTime();
            sent.forEach(client::accept);
            long micros = (System.nanoTime() - t0) / 1000;
            ClientStatus away = client.status();
            assertThat(away.connected()).isFalse();
            assertThat(away.inMemory()).isEqualTo(1000);
            assertThat(away.inJournal()).isEqualTo(49_000);
            assertThat(Files.list(journal).count()).isPositive();
            assertThat(micros).as("accept never waits for the absent logger").isLessThan(5_000_000);
            try (FakeLogger logger = new FakeLogger(port)) {
                assertThat(client.flush(30_000)).isTrue();
                assertThat(logger.received()).isEqualTo(sent);
                assertThat(client.status().inJournal()).isZero();
            }
        }
        assertThat(journal).doesNotExist();
    }

    @Test
    void shouldCountAndReportLossOnlyWhenEvenTheJournalIsFull() throws Exception {
        int port = freePort();
        try (LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", port, "core")
                .withMemoryEvents(1000).withJournal(folder.resolve("small"), 64 * 500).withFlushTimeout(java.time.Duration.ofSeconds(1)))) {
            events(3000).forEach(client::accept);
            ClientStatus s = client.status();
            assertThat(s.lost()).isPositive();
            assertThat(s.accepted() + s.lost()).isEqualTo(3000);
            assertThat(s.inMemory() + s.inJournal()).isEqualTo(s.accepted());
        }
    }

    @Test
    void shouldResendWhatWasNotAcknowledgedAfterTheLoggerRestarts() throws Exception {
        int port = freePort();
        List<NetworkEvent> sent = events(20_000);
        try (LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", port, "core")
                .withJournal(folder.resolve("j3"), 64 << 20))) {
            FakeLogger first = new FakeLogger(port);
            sent.subList(0, 10_000).forEach(client::accept);
            assertThat(client.flush(30_000)).isTrue();
            List<NetworkEvent> kept = first.received();
            first.close();
            sent.subList(10_000, 20_000).forEach(client::accept);
            Thread.sleep(300);
            try (FakeLogger second = new FakeLogger(port, kept)) {
                assertThat(client.flush(30_000)).isTrue();
                assertThat(second.received()).isEqualTo(sent);
            }
        }
    }
}

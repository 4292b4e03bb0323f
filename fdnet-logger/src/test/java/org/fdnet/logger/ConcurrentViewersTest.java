package org.fdnet.logger;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.Future;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.event.client.ViewerClient;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

@Timeout(value = 120, unit = TimeUnit.SECONDS)
class ConcurrentViewersTest {
    @TempDir
    static Path folder;
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    @Test
    void shouldServeAHundredConcurrentViewersTheSameCompleteHistoryWhileACoreProduces() throws Exception {
        ExecutorService pool = Executors.newFixedThreadPool(100);
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig())) {
            logger.start();
            try (LoggerClient core = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(),
                    "viewed-core").withJournal(folder.resolve("j"), 16 << 20))) {
                TestEvents events = new TestEvents(4);
                events.name(core);
                for (int i = 0; i < 5000; i++) {
                    events.produce(core);
                }
                assertThat(core.flush(30_000)).isTrue();
                Producer more = new Producer(new TestEvents(4), core, 5);
                AtomicInteger monitored = new AtomicInteger();
                List<Future<Integer>> answers = new ArrayList<>();
                for (int v = 0; v < 100; v++) {
                    int viewerNo = v;
                    answers.add(pool.submit(() -> {
                        try (ViewerClient viewer = new ViewerClient("127.0.0.1", logger.senderPort(), "viewer-" + viewerNo,
                                e -> monitored.incrementAndGet())) {
                            int id = viewer.nodes("arm/Joint2").get(0).sourceId();
                            viewer.monitor(id);
                            long firstRunEnd = Long.MAX_VALUE;
                            int n = viewer.history(new int[] {id}, 0, firstRunEnd).size();
                            Thread.sleep(300);
                            viewer.unmonitor();
                            return n;
                        }
                    }));
                }
                List<Integer> sizes = new ArrayList<>();
                for (Future<Integer> f : answers) {
                    sizes.add(f.get(90, TimeUnit.SECONDS));
                }
                more.stop();
                assertThat(sizes).hasSize(100).allMatch(n -> n >= 1200);
                assertThat(monitored.get()).isPositive();
            }
        } finally {
            pool.shutdownNow();
        }
    }
}

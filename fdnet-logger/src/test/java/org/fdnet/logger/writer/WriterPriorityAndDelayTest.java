package org.fdnet.logger.writer;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.Statement;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.UUID;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.PostgresPerClass;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.cache.RunProgress;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * Two writer settings on a real PostgreSQL: {@code priority.enabled} raises every thread that writes — the one
 * that hands batches out and each connection's thread that sorts, COPYs and COMMITs — at the cache's critical
 * level and lowers them at the normal level; {@code writer.writingDelayMillis} keeps each event in the cache
 * at least that long before it is written.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class WriterPriorityAndDelayTest {
    private static final String DISPATCH = "fdnet-logger-writer";
    private static final String LANE = "fdnet-writer-connection-";

    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    @Test
    void shouldRaiseEveryWritingThreadAtTheCriticalLevelAndLowerThemAtTheNormalLevel() throws Exception {
        // Events wait a minute (writingDelay) unless the cache is critical: the writer takes none before that.
        LoggerConfig config = database.fixture().loggerConfig().set(LoggerSetting.MEMORY_CAPACITY_MB, "1")
                .set(LoggerSetting.PRIORITY_ENABLED, "true").set(LoggerSetting.WRITER_CONNECTIONS, "2")
                .set(LoggerSetting.WRITER_DELAY, "60000").set(LoggerSetting.WRITER_BATCH_SIZE, "500")
                .set(LoggerSetting.WRITER_RECONNECT_DELAY, "100").set(LoggerSetting.WRITER_RECONNECT_ATTEMPTS, "1000");
        try (NetworkStateLogger logger = new NetworkStateLogger(config)) {
            logger.start();
            EventCache cache = logger.cache();
            RunProgress run = logger.directory().openRun(UUID.randomUUID(), "priority-core");
            int[] ids = WriterTestEvents.ids(logger.directory(), run, 10);
            awaitPriorities(Thread.NORM_PRIORITY, "at start");

            // Another session holds the run's row: every commit waits for it and fails, so the writer stays at
            // the critical level, writing, until the row is let go.
            int total = 0;
            try (Connection holder = database.fixture().target().open()) {
                holder.setAutoCommit(false);
                try (Statement s = holder.createStatement()) {
                    s.execute("SELECT * FROM fdnet_run WHERE run_id = " + run.runId() + " FOR UPDATE");
                }
                while (!cache.pressured()) {
                    cache.add(WriterTestEvents.events(cache, run, ids, total, 500));
                    total += 500;
                }
                Map<String, Integer> raised = awaitPriorities(Thread.MAX_PRIORITY, "at the critical level");
                assertThat(raised).as("the dispatch thread and both connections' threads")
                        .containsOnlyKeys(DISPATCH, LANE + "1", LANE + "2");
                holder.rollback();
            }
            while (cache.pressured()) {
                Thread.sleep(20);
            }
            awaitPriorities(Thread.NORM_PRIORITY, "back at the normal level");
            assertThat(cache.committedCount()).as("written while raised").isPositive();
        }
    }

    @Test
    void shouldKeepEveryEventInTheCacheAtLeastTheWritingDelay() throws Exception {
        long delayMillis = 1500;
        LoggerConfig config = database.fixture().loggerConfig().set(LoggerSetting.WRITER_DELAY, Long.toString(delayMillis))
                .set(LoggerSetting.WRITER_BATCH_TIMEOUT, "50").set(LoggerSetting.WRITER_BATCH_SIZE, "100");
        try (NetworkStateLogger logger = new NetworkStateLogger(config)) {
            logger.start();
            EventCache cache = logger.cache();
            RunProgress run = logger.directory().openRun(UUID.randomUUID(), "delay-core");
            int[] ids = WriterTestEvents.ids(logger.directory(), run, 5);
            List<Long> ageAtCommitNanos = new CopyOnWriteArrayList<>();
            logger.writer().observe(batch -> {
                long now = System.nanoTime();
                batch.forEach(e -> ageAtCommitNanos.add(now - e.arrivalNanos()));
            });
            int total = 0;
            for (int round = 0; round < 5; round++) {
                cache.add(WriterTestEvents.events(cache, run, ids, total, 200));
                total += 200;
                Thread.sleep(200);
            }
            WriterTestEvents.awaitCommitted(cache, total);
            assertThat(ageAtCommitNanos).hasSize(total)
                    .allMatch(age -> age >= TimeUnit.MILLISECONDS.toNanos(delayMillis), "at least the writing delay old");
        }
    }

    /** Waits until every writing thread has {@code priority}; returns them by name with their priorities. */
    private static Map<String, Integer> awaitPriorities(int priority, String when) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (true) {
            Map<String, Integer> now = writingThreads();
            if (!now.isEmpty() && now.values().stream().allMatch(p -> p == priority)) {
                return now;
            }
            assertThat(System.nanoTime()).as("writing threads %s %s, expected all at %d", now, when, priority)
                    .isLessThan(deadline);
            Thread.sleep(20);
        }
    }

    private static Map<String, Integer> writingThreads() {
        Map<String, Integer> out = new TreeMap<>();
        for (Thread t : Thread.getAllStackTraces().keySet()) {
            if (t.getName().equals(DISPATCH) || t.getName().startsWith(LANE)) {
                out.put(t.getName(), t.getPriority());
            }
        }
        return out;
    }
}

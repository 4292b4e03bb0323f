package org.fdnet.logger.writer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.TimeUnit;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.ValueType;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.PostgresPerClass;
import org.fdnet.logger.cache.CachedEvent;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.cache.RunProgress;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.logger.store.SourceDirectory;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/** The writer grows its batches with a backlog, keeps exactly-once and shrinks back when caught up. */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class BatchGrowthTest {
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    @Test
    void shouldWriteABacklogInGrowingBatchesExactlyOnceAndShrinkBackWhenCaughtUp() throws Exception {
        var config = database.fixture().loggerConfig().set(LoggerSetting.WRITER_BATCH_SIZE, "100")
                .set(LoggerSetting.WRITER_MAX_BATCH_ROWS, "5000");
        try (NetworkStateLogger logger = new NetworkStateLogger(config)) {
            logger.start();
            EventCache cache = logger.cache();
            SourceDirectory directory = logger.directory();
            RunProgress run = directory.openRun(UUID.randomUUID(), "backlog-core");
            int[] ids = new int[10];
            for (int i = 0; i < ids.length; i++) {
                ids[i] = directory.globalId(run, i);
            }
            long batchesBefore = logger.writer().batches();
            cache.add(WriterTestEvents.events(cache, run, ids, 0, 20_000));
            WriterTestEvents.awaitCommitted(cache, 20_000);

            long backlogBatches = logger.writer().batches() - batchesBefore;
            // Batches of 100 would take 200; growing 100, 200, ... up to 5,000 takes a handful.
            assertThat(backlogBatches).isLessThan(50);
            String ofRun = " FROM datavalue_log WHERE sourceid IN (SELECT sourceid FROM fdnet_node WHERE run_id = "
                    + run.runId() + ")";
            assertThat(database.fixture().count("SELECT count(*)" + ofRun)).isEqualTo(20_000);
            assertThat(database.fixture().count("SELECT count(DISTINCT (sourceid, time))" + ofRun)).isEqualTo(20_000);
            assertThat(database.fixture().count("SELECT committed_seq FROM fdnet_run WHERE run_id = " + run.runId()))
                    .isEqualTo(20_000);

            cache.add(WriterTestEvents.events(cache, run, ids, 20_000, 30));
            WriterTestEvents.awaitCommitted(cache, 20_030);
            assertThat(logger.writer().lastBatchRows()).isEqualTo(30);
            assertThat(logger.status().line()).contains("batch 30 (max 5,000)");
            assertThat(database.fixture().count("SELECT committed_seq FROM fdnet_run WHERE run_id = " + run.runId()))
                    .isEqualTo(20_030);
        }
    }

    @Test
    void shouldCapABatchAtTheConfiguredBytes() throws Exception {
        // 1 MB at 167 + 3 bytes per event: at most 6,168 events per batch, whatever the row maximum.
        var config = database.fixture().loggerConfig().set(LoggerSetting.WRITER_BATCH_SIZE, "1000")
                .set(LoggerSetting.WRITER_MAX_BATCH_ROWS, "1000000").set(LoggerSetting.WRITER_MAX_BATCH_BYTES, "1");
        try (NetworkStateLogger logger = new NetworkStateLogger(config)) {
            logger.start();
            EventCache cache = logger.cache();
            RunProgress run = logger.directory().openRun(UUID.randomUUID(), "bytes-core");
            int[] ids = {logger.directory().globalId(run, 0)};
            long before = logger.writer().batches();
            cache.add(WriterTestEvents.events(cache, run, ids, 0, 50_000));
            WriterTestEvents.awaitCommitted(cache, 50_000);
            assertThat(logger.writer().batches() - before).isGreaterThanOrEqualTo(50_000 / 6_168);
            assertThat(database.fixture().count("SELECT count(*) FROM datavalue_log WHERE sourceid = " + ids[0]))
                    .isEqualTo(50_000);
        }
    }

    @Test
    void shouldGiveAFreeLaneAtLeastTheFloorBesideTheOtherUnderAClosedLoop() throws Exception {
        // A client window of 60,000 unacknowledged events, two connections: a lane that frees while the other
        // writes gets the next batch once the floor's worth is ready, never a batch of a few rows that holds it
        // until the batch before commits.
        int window = 60_000;
        int total = 401_000; // 1,000 first, then 80 x 5,000
        var config = database.fixture().loggerConfig().set(LoggerSetting.WRITER_BATCH_SIZE, "1000")
                .set(LoggerSetting.WRITER_MAX_BATCH_ROWS, "200000").set(LoggerSetting.WRITER_CONNECTIONS, "2");
        try (NetworkStateLogger logger = new NetworkStateLogger(config)) {
            logger.start();
            EventCache cache = logger.cache();
            SourceDirectory directory = logger.directory();
            RunProgress run = directory.openRun(UUID.randomUUID(), "closed-loop-core");
            int[] ids = new int[10];
            for (int i = 0; i < ids.length; i++) {
                ids[i] = directory.globalId(run, i);
            }
            cache.add(WriterTestEvents.events(cache, run, ids, 0, 1000));
            WriterTestEvents.awaitCommitted(cache, 1000);
            List<Integer> sizes = new java.util.concurrent.CopyOnWriteArrayList<>();
            logger.writer().observe(b -> sizes.add(b.size()));
            long overlappedBefore = logger.writer().overlappedBatches();
            long overlappedRowsBefore = logger.writer().overlappedRows();
            int sent = 1000;
            while (sent < total) {
                if (sent - cache.committedCount() + 5000 <= window) {
                    cache.add(WriterTestEvents.events(cache, run, ids, sent, 5000));
                    sent += 5000;
                } else {
                    Thread.sleep(1);
                }
            }
            WriterTestEvents.awaitCommitted(cache, total);

            long overlapped = logger.writer().overlappedBatches() - overlappedBefore;
            assertThat(overlapped).as("batches COPYed while another was in flight").isPositive();
            assertThat(logger.writer().overlappedRows() - overlappedRowsBefore).as("their events")
                    .isGreaterThanOrEqualTo(overlapped * BatchSizer.PIPELINE_FLOOR_ROWS);
            assertThat(sizes.stream().mapToLong(Integer::longValue).sum()).isEqualTo(total - 1000);
            assertThat(database.fixture().count("SELECT committed_seq FROM fdnet_run WHERE run_id = " + run.runId()))
                    .isEqualTo(total);
            assertThat(database.fixture().count("SELECT count(DISTINCT (sourceid, time)) FROM datavalue_log WHERE sourceid"
                    + " IN (SELECT sourceid FROM fdnet_node WHERE run_id = " + run.runId() + ")")).isEqualTo(total);
        }
    }
}

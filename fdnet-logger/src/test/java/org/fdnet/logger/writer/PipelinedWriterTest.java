package org.fdnet.logger.writer;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.Connection;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.ValueType;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.PostgresPerClass;
import org.fdnet.logger.cache.CachedEvent;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.cache.RunProgress;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.logger.store.EventStore;
import org.fdnet.logger.store.NodeMapping;
import org.fdnet.logger.store.SourceDirectory;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * The writer with two connections (real PostgreSQL): batch N+1 is COPYed while N is in flight, commits stay
 * in order, a failure of N rolls N+1 back and both land once, and two open transactions that lock each other
 * end in a rollback and an in-order retry, not a hang.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class PipelinedWriterTest {
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    private static LoggerConfig config(int connections) {
        return database.fixture().loggerConfig().set(LoggerSetting.WRITER_BATCH_SIZE, "500")
                .set(LoggerSetting.WRITER_MAX_BATCH_ROWS, "4000")
                .set(LoggerSetting.WRITER_CONNECTIONS, Integer.toString(connections));
    }

    @Test
    void shouldCommitBatchesInOrderAndEveryEventOnceWithTwoConnectionsUnderLoad() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(config(2))) {
            logger.start();
            EventCache cache = logger.cache();
            RunProgress run = logger.directory().openRun(UUID.randomUUID(), "pipeline-core");
            int[] ids = WriterTestEvents.ids(logger.directory(), run, 20);
            List<long[]> committedRanges = new ArrayList<>();
            List<Long> acksAtCommit = new ArrayList<>();
            logger.writer().observe(batch -> {
                committedRanges.add(seqRange(batch));
                acksAtCommit.add(run.committed());
            });
            int total = 150_000;
            for (int first = 0; first < total; first += 10_000) {
                cache.add(WriterTestEvents.events(cache, run, ids, first, 10_000));
            }
            WriterTestEvents.awaitCommitted(cache, total);

            assertThat(logger.writer().connections()).isEqualTo(2);
            assertThat(logger.writer().overlappedBatches()).as("batches COPYed while another was in flight").isPositive();
            for (int i = 1; i < committedRanges.size(); i++) {
                assertThat(committedRanges.get(i)[0]).as("batch %d starts right after batch %d", i, i - 1)
                        .isEqualTo(committedRanges.get(i - 1)[1] + 1);
                assertThat(acksAtCommit.get(i)).as("acknowledged at least up to batch %d when it left the cache", i)
                        .isGreaterThanOrEqualTo(committedRanges.get(i)[1]);
            }
            assertStoredOnce(run, total);
            assertThat(logger.status().line()).contains("2 writer connections");
        }
    }

    @Test
    void shouldRollBackTheBatchBehindAFailedOneAndWriteBothOnceAfterwards() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(config(2))) {
            logger.start();
            EventCache cache = logger.cache();
            RunProgress run = logger.directory().openRun(UUID.randomUUID(), "failing-core");
            int[] ids = WriterTestEvents.ids(logger.directory(), run, 20);
            cache.add(WriterTestEvents.events(cache, run, ids, 0, 1000));
            WriterTestEvents.awaitCommitted(cache, 1000);
            int total = 1000;
            // Another session holds the run's row: batch N's watermark UPDATE waits for it until the writer's
            // lock timeout fails N; N+1, already COPYed, must be rolled back, then both are written in order.
            try (Connection holder = database.fixture().target().open()) {
                holder.setAutoCommit(false);
                try (Statement s = holder.createStatement()) {
                    s.execute("SELECT * FROM fdnet_run WHERE run_id = " + run.runId() + " FOR UPDATE");
                }
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
                while (logger.writer().rolledBackBehind() == 0 && System.nanoTime() < deadline) {
                    if (total < 300_000) {
                        cache.add(WriterTestEvents.events(cache, run, ids, total, 5000));
                        total += 5000;
                    }
                    Thread.sleep(50);
                }
                assertThat(cache.committedCount()).as("nothing committed past the held row").isEqualTo(1000);
                holder.rollback();
            }
            assertThat(logger.writer().rolledBackBehind()).as("batches rolled back behind the failed one").isPositive();
            WriterTestEvents.awaitCommitted(cache, total);
            assertStoredOnce(run, total);
            assertThat(logger.writer().databaseState()).isEqualTo("connected");
        }
    }

    @Test
    void shouldTurnTwoOpenTransactionsWaitingForEachOtherIntoARollbackAndAnInOrderRetry() throws Exception {
        // The hazard the writer avoids by writing batches with names or mappings alone: batch N+1 renames a
        // node first and holds its row while it waits (in the client) for N's commit; N renames the same node
        // and waits for N+1's row lock. PostgreSQL sees no deadlock; the lock timeout must end it.
        try (EventStore store = new EventStore(database.fixture().target())) {
            store.createSchema();
            SourceDirectory directory = new SourceDirectory(store);
            RunProgress run = directory.openRun(UUID.randomUUID(), "hazard-core");
            int[] ids = WriterTestEvents.ids(directory, run, 2);
            List<NodeMapping> mappings = directory.unsavedMappings();
            try (Connection c = store.openWriterConnection()) {
                store.writeBatch(c, named(run, ids[0], "First", 1, 1_000), mappings);
                directory.saved(mappings);
            }
            List<CachedEvent> batchN = named(run, ids[0], "Second", 2, 2_000);
            List<CachedEvent> batchN1 = named(run, ids[0], "Third", 3, 3_000);
            try (WriterLane laneA = new WriterLane(store, "test-lane-a", Thread.NORM_PRIORITY);
                 WriterLane laneB = new WriterLane(store, "test-lane-b", Thread.NORM_PRIORITY)) {
                CompletableFuture<Void> nDone = new CompletableFuture<>();
                CompletableFuture<Void> n1 = laneB.write(batchN1, List.of(), nDone);
                awaitOpenTransactionHoldingALock();
                laneA.write(batchN, List.of(), CompletableFuture.completedFuture(null))
                        .whenComplete((ok, failure) -> {
                            if (failure == null) {
                                nDone.complete(null);
                            } else {
                                nDone.completeExceptionally(failure);
                            }
                        });
                assertThat(failureOf(nDone)).isInstanceOf(SQLException.class);
                assertThat(((SQLException) failureOf(nDone)).getSQLState()).as("lock_not_available").isEqualTo("55P03");
                assertThat(failureOf(n1)).isInstanceOf(WriterLane.RolledBackBehindFailure.class);

                // the writer's retry after a failure: one batch at a time, in order
                CompletableFuture<Void> nAgain = laneA.write(batchN, List.of(), CompletableFuture.completedFuture(null));
                assertThat(failureOf(nAgain)).as("batch N written again").isNull();
                CompletableFuture<Void> n1Again = laneB.write(batchN1, List.of(), nAgain);
                assertThat(failureOf(n1Again)).as("then batch N+1").isNull();
            }
            assertThat(database.fixture().text("SELECT node FROM fdnet_node WHERE sourceid = " + ids[0])).isEqualTo("Third");
            assertThat(database.fixture().count("SELECT count(*) FROM datavalue_log WHERE sourceid = " + ids[0]))
                    .isEqualTo(3);
            assertThat(database.fixture().count("SELECT committed_seq FROM fdnet_run WHERE run_id = " + run.runId()))
                    .isEqualTo(3);
        }
    }

    @Test
    void shouldWriteNewNodesAndNamesArrivingUnderBacklogWithTwoConnections() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(config(2))) {
            logger.start();
            EventCache cache = logger.cache();
            SourceDirectory directory = logger.directory();
            RunProgress run = directory.openRun(UUID.randomUUID(), "growing-core");
            long seq = 0;
            int nodes = 0;
            for (int round = 0; round < 30; round++) {
                // a new node, named, then a burst of values of every node so far: names land mid-backlog
                int id = directory.globalId(run, nodes++);
                List<CachedEvent> chunk = new ArrayList<>();
                NodeNamedEvent name = new NodeNamedEvent(id, 10L * round, NodeKind.DATA, new NodeRef("arm", "Joint" + round));
                directory.named(run, name);
                chunk.add(new CachedEvent(name, run, ++seq, cache.sizeOf(name), System.nanoTime()));
                for (int i = 0; i < 3000; i++) {
                    int node = directory.globalId(run, i % nodes);
                    DataValueEvent e = new DataValueEvent(node, 1_000_000L + seq, ValueType.DOUBLE, "1.5");
                    chunk.add(new CachedEvent(e, run, ++seq, cache.sizeOf(e), System.nanoTime()));
                }
                cache.add(chunk);
            }
            WriterTestEvents.awaitCommitted(cache, seq);
            assertThat(database.fixture().count("SELECT count(*) FROM fdnet_node WHERE node IS NOT NULL AND run_id = "
                    + run.runId())).isEqualTo(30);
            assertThat(database.fixture().count("SELECT count(*) FROM datavalue_log WHERE sourceid IN (SELECT sourceid"
                    + " FROM fdnet_node WHERE run_id = " + run.runId() + ")")).isEqualTo(seq - 30);
            assertThat(database.fixture().count("SELECT committed_seq FROM fdnet_run WHERE run_id = " + run.runId()))
                    .isEqualTo(seq);
        }
    }

    @Test
    void shouldWriteOneBatchAtATimeWithOneConnection() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(config(1))) {
            logger.start();
            EventCache cache = logger.cache();
            RunProgress run = logger.directory().openRun(UUID.randomUUID(), "single-core");
            int[] ids = WriterTestEvents.ids(logger.directory(), run, 10);
            List<long[]> ranges = new ArrayList<>();
            logger.writer().observe(batch -> ranges.add(seqRange(batch)));
            cache.add(WriterTestEvents.events(cache, run, ids, 0, 30_000));
            WriterTestEvents.awaitCommitted(cache, 30_000);
            assertThat(logger.writer().overlappedBatches()).isZero();
            for (int i = 1; i < ranges.size(); i++) {
                assertThat(ranges.get(i)[0]).isEqualTo(ranges.get(i - 1)[1] + 1);
            }
            assertStoredOnce(run, 30_000);
            assertThat(logger.status().line()).contains("1 writer connection |");
        }
    }

    private static void awaitOpenTransactionHoldingALock() throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (database.fixture().count("SELECT count(*) FROM pg_stat_activity WHERE state = 'idle in transaction'"
                + " AND datname = current_database()") == 0) {
            assertThat(System.nanoTime()).as("batch N+1 COPYed and waiting").isLessThan(deadline);
            Thread.sleep(20);
        }
    }

    private static Throwable failureOf(CompletableFuture<Void> f) throws Exception {
        try {
            f.get(30, TimeUnit.SECONDS);
            return null;
        } catch (ExecutionException e) {
            return e.getCause();
        }
    }

    private static List<CachedEvent> named(RunProgress run, int id, String node, long seq, long time) {
        NodeNamedEvent name = new NodeNamedEvent(id, time, NodeKind.DATA, new NodeRef("arm", node));
        DataValueEvent value = new DataValueEvent(id, time + 1, ValueType.DOUBLE, "2.5");
        return List.of(new CachedEvent(name, run, seq, 100, System.nanoTime()),
                new CachedEvent(value, run, seq, 100, System.nanoTime()));
    }

    private static long[] seqRange(List<CachedEvent> batch) {
        long min = Long.MAX_VALUE;
        long max = Long.MIN_VALUE;
        for (CachedEvent e : batch) {
            min = Math.min(min, e.seq());
            max = Math.max(max, e.seq());
        }
        return new long[] {min, max};
    }

    private static void assertStoredOnce(RunProgress run, long total) throws SQLException {
        String ofRun = " FROM datavalue_log WHERE sourceid IN (SELECT sourceid FROM fdnet_node WHERE run_id = "
                + run.runId() + ")";
        assertThat(database.fixture().count("SELECT count(*)" + ofRun)).isEqualTo(total);
        assertThat(database.fixture().count("SELECT count(DISTINCT (sourceid, time))" + ofRun)).isEqualTo(total);
        assertThat(database.fixture().count("SELECT committed_seq FROM fdnet_run WHERE run_id = " + run.runId()))
                .isEqualTo(total);
    }
}

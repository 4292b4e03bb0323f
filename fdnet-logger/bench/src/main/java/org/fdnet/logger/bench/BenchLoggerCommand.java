package org.fdnet.logger.bench;

import java.lang.management.ManagementFactory;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.LongSupplier;
import org.HdrHistogram.Histogram;
import org.fdnet.event.client.ViewerClient;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.cache.CachedEvent;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.cache.MonitorSubscriber;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.logger.store.EmbeddedDatabase;
import org.fdnet.logger.store.QueryPriority;
import org.fdnet.logger.store.SourceDirectory;
import org.fdnet.logger.writer.BatchWriter;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code fdnet bench logger}, end to end: producer processes (a core's real client) → TCP → receiver →
 * cache → writer → PostgreSQL (embedded, fsync on), beside baselines measured in the same run on the same
 * database. Four phases:
 * <ol>
 *   <li>sustained: as fast as the logger takes them, {@code --seconds}; loss counted in the database;</li>
 *   <li>baselines: raw COPY of the same rows in the batch sizes the writer used — on one connection, and
 *       pipelined on as many connections as the writer used (the like-for-like ratio) — and the keyed-COPY
 *       limit (100,000-row sorted batches) on one and on two connections;</li>
 *   <li>event-to-commit latency at a moderate rate ({@code --latency-rate});</li>
 *   <li>a burst through TCP with the default cache; a viewer's query (in-process and over TCP through a
 *       {@code ViewerClient}) while the writer drains it and once idle; the burst counted in the database.</li>
 * </ol>
 * Every figure is printed beside its target with met / NOT MET, and again in a summary at the end.
 */
@Command(name = "logger", mixinStandardHelpOptions = true,
        description = "Benchmark the logger end to end against raw COPY (same run, same database, fsync on).")
public final class BenchLoggerCommand implements Callable<Integer> {
    private static final int QUERY_NODE = 7;
    private static final long TEN_SECONDS_US = 10_000_000L;
    /** Queries over TCP before each measured set: their figure is printed on its own. */
    private static final int WARM_UP_QUERIES = 50;
    /** The pause [4] compares with when the setting does not pause. */
    private static final long PAUSING_MILLIS = 20;

    @Option(names = "--seconds", defaultValue = "60", description = "sustained phase length (default 60)")
    long seconds;

    @Option(names = "--events", defaultValue = "1000000000", description = "sustained phase: events at most (default: --seconds decides)")
    long events;

    @Option(names = "--batch", defaultValue = "1000", description = "writer.batchSize, the thesis's latency setting (default 1000)")
    int batch;

    @Option(names = "--max-batch", defaultValue = "200000", description = "writer.maxBatchRows: batches grow up to this under backlog (default 200000)")
    int maxBatch;

    @Option(names = "--connections", defaultValue = "2", description = "writer.connections: batches in flight at once, one per connection (default 2)")
    int connections;

    @Option(names = "--nodes", defaultValue = "100", description = "Data nodes of the sustained producer (default 100)")
    int nodes;

    @Option(names = "--latency-rate", defaultValue = "50000", description = "events/s of the latency phase (default 50000)")
    long latencyRate;

    @Option(names = "--latency-seconds", defaultValue = "20", description = "latency phase length (default 20)")
    long latencySeconds;

    @Option(names = "--burst", defaultValue = "5000000", description = "events of the burst (default 5,000,000)")
    long burst;

    @Option(names = "--cache-mb", defaultValue = "512", description = "memory.cacheCapacityMegabytes (default 512, the logger's default)")
    int cacheMb;

    @Option(names = "--backend-niceness", description = "writer.backendNiceness: the nice value of the writer's PostgreSQL"
            + " backends (default: the logger's default, 10; 0 leaves them at the server's)")
    Integer backendNiceness;

    @Option(names = "--compare-binary", description = "also time the raw COPY baseline in binary COPY format")
    boolean compareBinary;

    @Option(names = "--tls", description = "then [5]: the cost of mutual TLS — a producer at full speed and viewer"
            + " queries, plain then TLS, each into a fresh logger on the same database (--tls-seconds each)")
    boolean tls;

    @Option(names = "--tls-seconds", defaultValue = "15", description = "length of each [5] producer run (default 15)")
    int tlsSeconds;

    @Option(names = "--db", description = "external database jdbc:postgresql://... (default: a fresh embedded one, fsync on)")
    String db;

    private final TargetReport report = new TargetReport();
    private final AtomicLong peakHeap = new AtomicLong();
    /** The last in-process query figure: the baseline printed beside the TCP figure of the same phase. */
    private String inProcessFigure = "n/a";

    @Override
    public Integer call() throws Exception {
        Path dir = Files.createTempDirectory("fdnet-bench-logger");
        EmbeddedDatabase embedded = db == null ? EmbeddedDatabase.startThrowaway(dir.resolve("pg")) : null;
        DatabaseTarget target = embedded != null ? embedded.target() : new DatabaseTarget(db, "postgres", "");
        try {
            System.out.printf("fdnet bench logger: sustained %d s, batch %d growing to %d, %d nodes; latency at %,d/s for %d s;"
                            + " burst %,d events, cache %d MB; database %s, fsync %s%n", seconds, batch, maxBatch, nodes,
                    latencyRate, latencySeconds, burst, cacheMb, target.url(), show(target, "fsync"));
            LoggerConfig config = new LoggerConfig()
                    .set(LoggerSetting.DATABASE_EMBEDDED, "false").set(LoggerSetting.DATABASE_URL, target.url())
                    .set(LoggerSetting.DATABASE_USER, target.user())
                    .set(LoggerSetting.WRITER_BATCH_SIZE, Integer.toString(batch))
                    .set(LoggerSetting.WRITER_MAX_BATCH_ROWS, Integer.toString(maxBatch))
                    .set(LoggerSetting.WRITER_CONNECTIONS, Integer.toString(connections))
                    .set(LoggerSetting.RECEIVER_PORT, "0").set(LoggerSetting.SENDER_PORT, "0")
                    .set(LoggerSetting.MEMORY_CAPACITY_MB, Integer.toString(cacheMb));
            if (backendNiceness != null) {
                config.set(LoggerSetting.WRITER_BACKEND_NICENESS, Integer.toString(backendNiceness));
            }
            Thread heap = heapSampler();
            try (NetworkStateLogger logger = new NetworkStateLogger(config)) {
                logger.start();
                System.out.printf("writer: batch %d, timer %d ms, max %,d rows / %d MB, %d connection(s), backends at nice %d;"
                                + " cache %d MB, critical %d%%, normal %d%%; viewer queries pause bulk work up to %d ms%n",
                        batch, config.batchTimeoutMillis(), config.maxBatchRows(), config.maxBatchBytes() >> 20,
                        config.writerConnections(), config.backendNiceness(), cacheMb, config.criticalPercent(),
                        config.normalPercent(), config.queryPauseMillis());
                Sustained s = sustained(logger, target);
                baselines(target, s, config);
                latency(logger, config.batchTimeoutMillis());
                burstAndQueries(logger, target);
            } finally {
                heap.interrupt();
            }
            if (tls) {
                new LoggerTlsCost(config, target, tlsSeconds, nodes).run();
            }
            report.info("peak heap (logger JVM)", String.format("%,d MiB", peakHeap.get() >> 20));
            report.printSummary();
            return 0;
        } finally {
            if (embedded != null) {
                embedded.close();
            }
            Files.deleteIfExists(dir);
        }
    }

    private record Sustained(long stored, double rate, int[] batchSizes, int connections) {
    }

    /** Phase 1: one producer as fast as the logger takes its events. */
    private Sustained sustained(NetworkStateLogger logger, DatabaseTarget target) throws Exception {
        System.out.printf("%n[1] sustained: a producer process sends as fast as the logger takes (%d s) ...%n", seconds);
        BatchSizes sizes = new BatchSizes();
        AtomicLong firstCommit = new AtomicLong();
        AtomicLong lastCommit = new AtomicLong();
        logger.writer().observe(b -> {
            long now = System.nanoTime();
            firstCommit.compareAndSet(0, now);
            lastCommit.set(now);
            sizes.add(b.size());
        });
        long overlappedBefore = logger.writer().overlappedBatches();
        long busyBefore = logger.writer().laneBusyNanos();
        ProducerProcess.Outcome out;
        try (ProducerProcess producer = new ProducerProcess(logger.receiverPort(), events, seconds, nodes, 0, "sustained", false, 0)) {
            while (producer.isAlive()) {
                Thread.sleep(5000);
                if (producer.isAlive()) {
                    System.out.println("  ... " + logger.status().line());
                }
            }
            out = producer.outcome();
        }
        logger.writer().observe(null);
        long stored = count(target, "SELECT count(*) FROM datavalue_log");
        double secs = (lastCommit.get() - firstCommit.get()) / 1e9;
        double rate = stored / secs;
        long lost = out.accepted() - nodes - stored;
        System.out.printf("  %,d events stored in %.1f s (first to last commit) in %,d batches: mean %,.0f, largest %,d%n",
                stored, secs, sizes.count(), sizes.mean(), sizes.largest());
        System.out.printf("  writer: %,d of them COPYed while another was in flight; its %d connections busy %.0f %% of that time%n",
                logger.writer().overlappedBatches() - overlappedBefore, logger.writer().connections(),
                100.0 * (logger.writer().laneBusyNanos() - busyBefore) / (logger.writer().connections() * 1e9 * secs));
        report.check("[1] logger sustained, whole run", String.format("%,.0f events/s", rate), ">= 500,000 events/s",
                rate >= 500_000);
        report.check("[1] loss counted in the database", String.format("%,d (client accepted %,d values, stored %,d; client-side loss %d)",
                lost, out.accepted() - nodes, stored, out.lost()), "0", lost == 0 && out.lost() == 0);
        return new Sustained(stored, rate, sizes.toArray(), logger.writer().connections());
    }

    /** Phase 2: the same rows by raw COPY, with the writer's batch sizes and with 100,000-row batches. */
    private void baselines(DatabaseTarget target, Sustained s, LoggerConfig config) throws SQLException, InterruptedException {
        System.out.printf("%n[2] baselines: raw COPY of the same %,d rows, same table definition, one thread, at the writer's"
                + " priorities (backends at nice %d, threads at Java priority %d) ...%n", s.stored, config.backendNiceness(),
                BatchWriter.bulkPriority(config.priorityEnabled(), false));
        RawCopyBaseline baseline = new RawCopyBaseline(target, nodes, config.backendNiceness(),
                BatchWriter.bulkPriority(config.priorityEnabled(), false)); // at the writer's priorities
        double raw = baseline.run(s.stored, s.batchSizes, RawCopyBaseline.Format.TEXT);
        if (s.connections > 1) {
            System.out.printf("  ... and pipelined like the writer on %d connections (COPY while the batch before commits,"
                    + " commits in order) ...%n", s.connections);
            double pipelined = baseline.runPipelined(s.stored, s.batchSizes, s.connections);
            report.info("[2] raw COPY, the writer's batch sizes, " + s.connections + " connections pipelined, whole run",
                    String.format("%,.0f rows/s (%.2f x one connection)", pipelined, pipelined / raw));
            report.check("[2] ratio logger / raw COPY (same rows, batches and connections, whole run each)",
                    String.format("%.2f", s.rate / pipelined), ">= 0.80", s.rate / pipelined >= 0.8);
            report.info("[2] raw COPY, the writer's batch sizes, one connection", String.format("%,.0f rows/s (logger at %.2f of it)",
                    raw, s.rate / raw));
        } else {
            report.info("[2] raw COPY, the writer's batch sizes, whole run", String.format("%,.0f rows/s", raw));
            report.check("[2] ratio logger / raw COPY (same rows, same batches, whole run each)",
                    String.format("%.2f", s.rate / raw), ">= 0.80", s.rate / raw >= 0.8);
        }
        if (compareBinary) {
            double bin = baseline.run(s.stored, s.batchSizes, RawCopyBaseline.Format.BINARY);
            report.info("[2] raw COPY in binary format, the writer's batch sizes", String.format("%,.0f rows/s (%.2f x text)",
                    bin, bin / raw));
        }
        double keyed = baseline.run(s.stored, new int[] {100_000}, RawCopyBaseline.Format.TEXT);
        report.info("[2] keyed-COPY limit: 100,000-row sorted batches", String.format("%,.0f rows/s (logger at %.2f of it)",
                keyed, s.rate / keyed));
        double two = baseline.runParallel(s.stored, 100_000, 2);
        report.info("[2] keyed-COPY limit with 2 connections at once (disjoint nodes, 100,000-row batches)",
                String.format("%,.0f rows/s (%.2f x one connection; the logger writes through %d)", two, two / keyed,
                        s.connections));
        double limit = s.connections > 1 ? two : keyed;
        report.check("[2] ratio logger / keyed-COPY limit on the same " + s.connections + " connection(s) (issue #21)",
                String.format("%.2f (%,.0f of %,.0f rows/s)", s.rate / limit, s.rate, limit), ">= 0.75", s.rate / limit >= 0.75);
    }

    /** Phase 3: a moderate rate; for each event, from its time stamp in the core to the commit of its batch. */
    private void latency(NetworkStateLogger logger, long timerMillis) throws Exception {
        System.out.printf("%n[3] latency: a producer at %,d events/s for %d s ...%n", latencyRate, latencySeconds);
        Histogram h = new Histogram(3_600_000_000L, 3);
        logger.writer().observe(b -> {
            long now = nowMicros();
            for (CachedEvent e : b) {
                h.recordValue(Math.max(0, now - e.time()));
            }
        });
        long before = logger.cache().committedCount();
        try (ProducerProcess producer = new ProducerProcess(logger.receiverPort(), latencyRate * latencySeconds,
                latencySeconds + 30, nodes, latencyRate, "latency", false, 0)) {
            producer.outcome();
        }
        logger.writer().observe(null);
        long targetMicros = (timerMillis + 500) * 1000;
        long p99 = h.getValueAtPercentile(99);
        System.out.printf("  %,d events committed; event-to-commit p50 %,d us, p99 %,d us, max %,d us%n",
                logger.cache().committedCount() - before, h.getValueAtPercentile(50), p99, h.getMaxValue());
        report.check("[3] event-to-commit latency p99 at " + String.format("%,d", latencyRate) + " events/s",
                String.format("%.1f ms", p99 / 1000.0), String.format("<= timer + 0.5 s = %,d ms", timerMillis + 500),
                p99 <= targetMicros);
    }

    /** Phase 4: the burst through TCP; queries while the writer drains it and once it is idle. */
    private void burstAndQueries(NetworkStateLogger logger, DatabaseTarget target) throws Exception {
        int burstNodes = 1000;
        System.out.printf("%n[4] burst: %,d events of %d nodes from a producer process through TCP, cache %d MB ...%n",
                burst, burstNodes, cacheMb);
        EventCache cache = logger.cache();
        SourceDirectory directory = logger.directory();
        List<CachedEvent> held = new java.util.ArrayList<>();
        MonitorSubscriber plot = held::add; // a viewer plotting the node: its events stay in memory after their commit
        try (ProducerProcess producer = new ProducerProcess(logger.receiverPort(), burst, 3600, burstNodes, 0, "burst", true,
                (int) Math.min(Integer.MAX_VALUE, burst + burstNodes + 1000));
             ViewerClient viewer = new ViewerClient("127.0.0.1", logger.senderPort(), "bench-viewer", e -> { })) {
            producer.awaitNamed(120_000);
            List<org.fdnet.event.wire.LoggedNode> found = viewer.nodes("burst/Data" + QUERY_NODE);
            int node = found.get(0).sourceId();
            cache.subscribe(plot, new int[] {node});
            long receivedBefore = cache.received();
            long t0 = System.nanoTime();
            producer.go();
            while (cache.received() - receivedBefore < burst / 5 && producer.isAlive()) {
                Thread.sleep(10);
            }
            LongSupplier now = BenchLoggerCommand::nowMicros;
            inProcessQueries("while the writer drains", cache, directory, node, now, 1.0);
            onHistoryLoader(() -> tcpQueries("while the writer drains", viewer, cache, node, now, 2.0, logger.queries()));
            long inNanos = 0;
            while (producer.isAlive()) {
                if (inNanos == 0 && cache.received() - receivedBefore >= burst) {
                    inNanos = System.nanoTime() - t0;
                }
                Thread.sleep(10);
            }
            ProducerProcess.Outcome out = producer.outcome();
            long drainedNanos = System.nanoTime() - t0;
            inNanos = inNanos == 0 ? drainedNanos : inNanos;
            report.info("[4] burst taken in through TCP (receiver, back-pressure)", String.format("%,.0f events/s; all committed"
                    + " after %.1f s = %,.0f events/s", burst / (inNanos / 1e9), drainedNanos / 1e9, burst / (drainedNanos / 1e9)));
            long stored = count(target, "SELECT count(*) FROM datavalue_log WHERE sourceid IN (SELECT n.sourceid FROM fdnet_node n"
                    + " JOIN fdnet_run r ON r.run_id = n.run_id WHERE r.core_name = 'bench-burst')");
            long lost = out.accepted() - burstNodes - stored;
            report.check("[4] burst loss counted in the database", String.format("%,d (accepted %,d, stored %,d)", lost,
                    out.accepted() - burstNodes, stored), "0", lost == 0 && out.lost() == 0);
            cache.received(); // a volatile read after the last offer: the held events are visible (the burst is over)
            long newest = held.isEmpty() ? nowMicros() : held.get(held.size() - 1).time();
            LongSupplier end = () -> newest; // idle: the last 10 s of the node's data, now over
            inProcessQueries("writer idle", cache, directory, node, end, 1.0);
            onHistoryLoader(() -> tcpQueries("writer idle", viewer, cache, node, end, 1.0, null));
            cache.unsubscribe(plot, new int[] {node}, held);
        }
    }

    private interface Queries {
        void run() throws Exception;
    }

    /**
     * Runs {@code queries} the way {@code fdnet viewer} loads a history: on a thread of their own that makes
     * itself real-time where permitted ({@code HistoryLoader}, {@code ResponsiveThreads}), not on the bench's
     * main thread.
     */
    private static void onHistoryLoader(Queries queries) throws Exception {
        java.util.concurrent.atomic.AtomicReference<Exception> failure = new java.util.concurrent.atomic.AtomicReference<>();
        Thread loader = new Thread(() -> {
            org.fdnet.event.client.ResponsiveThreads.raiseCurrent("the bench's history loader");
            try {
                queries.run();
            } catch (Exception e) {
                failure.set(e);
            }
        }, "bench-history-loader");
        loader.start();
        loader.join();
        if (failure.get() != null) {
            throw failure.get();
        }
    }

    private void inProcessQueries(String when, EventCache cache, SourceDirectory directory, int node, LongSupplier end,
                                  double targetMs) {
        Histogram h = new Histogram(3);
        long gcBefore = gcMillis();
        long unwrittenBefore = cache.unwrittenCount();
        int found = 0;
        SlowQueries slow = new SlowQueries(targetMs);
        for (int i = 0; i < 2000; i++) {
            long to = end.getAsLong();
            long g0 = gcCount();
            long q0 = System.nanoTime();
            EventCache.CacheAnswer a = cache.history(node, to - TEN_SECONDS_US, to, directory.seenFromStart(node));
            long micros = (System.nanoTime() - q0) / 1000;
            h.recordValue(micros);
            slow.add(micros, gcCount() != g0);
            found = a.events().size();
        }
        queryFigure("in-process", when, h, found, unwrittenBefore, cache.unwrittenCount(), gcMillis() - gcBefore, targetMs, slow);
    }

    /**
     * 1,000 queries over TCP with the setting, after {@value #WARM_UP_QUERIES} more: those are the path's first calls in
     * this JVM, counted in the target's figure (a viewer in a fresh JVM pays them) and also shown apart, but kept out
     * of the comparison (its first block would otherwise carry them alone). With {@code priority}, a comparison is
     * measured in the same phase: blocks of 50 queries alternate between the logger's setting
     * ({@code sender.queryPauseMillis}) and the other choice — no pause if the setting pauses, else a pause of
     * {@value #PAUSING_MILLIS} ms — so both see the same load; the target is checked on the setting's queries.
     */
    private void tcpQueries(String when, ViewerClient viewer, EventCache cache, int node, LongSupplier end, double targetMs,
                            QueryPriority priority) throws Exception {
        Histogram h = new Histogram(3);
        Histogram other = new Histogram(3);
        long pauseMillis = Long.parseLong(LoggerSetting.SENDER_QUERY_PAUSE.defaultValue());
        long otherMillis = pauseMillis > 0 ? 0 : PAUSING_MILLIS;
        long gcBefore = gcMillis();
        long unwrittenBefore = cache.unwrittenCount();
        int found = 0;
        Thread.currentThread().setPriority(Thread.MAX_PRIORITY); // where real-time is refused: a viewer's waiting thread
        SlowQueries slow = new SlowQueries(targetMs);
        Histogram cold = new Histogram(3);
        for (int i = 0; i < WARM_UP_QUERIES; i++) { // the path's first calls in this JVM: shown, not mixed in
            long to = end.getAsLong();
            long q0 = System.nanoTime();
            viewer.historyColumns(new int[] {node}, to - TEN_SECONDS_US, to);
            long micros = (System.nanoTime() - q0) / 1000;
            cold.recordValue(micros);
            h.recordValue(micros); // the target's figure counts them: a viewer in a fresh JVM pays them
            slow.add(micros, false);
        }
        report.info("[4] the first " + WARM_UP_QUERIES + " queries over TCP, " + when + " (the path's first calls: in the"
                        + " target's figure, not in the comparison)", String.format("p50 / p99 / max %.2f / %.2f / %.1f ms",
                cold.getValueAtPercentile(50) / 1000.0, cold.getValueAtPercentile(99) / 1000.0, cold.getMaxValue() / 1000.0));
        for (int i = 0; i < (priority == null ? 1000 : 2000); i++) {
            boolean baseline = priority != null && (i / 50) % 2 == 1;
            if (priority != null && i % 50 == 0) {
                priority.maxPauseMillis(baseline ? otherMillis : pauseMillis);
            }
            long to = end.getAsLong();
            long g0 = gcCount();
            long q0 = System.nanoTime();
            found = viewer.historyColumns(new int[] {node}, to - TEN_SECONDS_US, to).size(); // a viewer's plot path
            long micros = (System.nanoTime() - q0) / 1000;
            if (baseline) {
                other.recordValue(micros);
                continue;
            }
            h.recordValue(micros);
            slow.add(micros, gcCount() != g0);
        }
        if (priority != null) {
            priority.maxPauseMillis(pauseMillis);
            report.info("[4] comparison: the same query over TCP, " + when + ", with sender.queryPauseMillis " + otherMillis
                            + " (blocks of 50 alternating with the setting's " + pauseMillis + ")",
                    String.format("p50 / p99 / max %.2f / %.2f / %.1f ms", other.getValueAtPercentile(50) / 1000.0,
                            other.getValueAtPercentile(99) / 1000.0, other.getMaxValue() / 1000.0));
        }
        Thread.currentThread().setPriority(Thread.NORM_PRIORITY);
        queryFigure("ViewerClient over TCP", when, h, found, unwrittenBefore, cache.unwrittenCount(), gcMillis() - gcBefore,
                targetMs, slow);
        eventsBaseline(when, viewer, node, end);
    }

    /** The same query as one object and String per event (ViewerClient.history, the path before columns). */
    private void eventsBaseline(String when, ViewerClient viewer, int node, LongSupplier end) throws Exception {
        Histogram h = new Histogram(3);
        int found = 0;
        Thread.currentThread().setPriority(Thread.MAX_PRIORITY);
        for (int i = 0; i < 1000; i++) {
            long to = end.getAsLong();
            long q0 = System.nanoTime();
            found = viewer.history(new int[] {node}, to - TEN_SECONDS_US, to).size();
            h.recordValue((System.nanoTime() - q0) / 1000);
        }
        Thread.currentThread().setPriority(Thread.NORM_PRIORITY);
        report.info("[4] baseline: the same query as events (ViewerClient.history), " + when + ": p50 / p99 / max",
                String.format("%.2f / %.2f / %.1f ms (%,d events)", h.getValueAtPercentile(50) / 1000.0,
                        h.getValueAtPercentile(99) / 1000.0, h.getMaxValue() / 1000.0, found));
    }

    private void queryFigure(String how, String when, Histogram h, int found, long unwrittenBefore, long unwrittenAfter,
                             long gc, double targetMs, SlowQueries slow) {
        System.out.printf("  query of the last 10 s of one monitored node (%,d events) %s, %s: unwritten %,d -> %,d,"
                + " GC %d ms meanwhile; %s%n", found, how, when, unwrittenBefore, unwrittenAfter, gc, slow);
        double p99 = h.getValueAtPercentile(99) / 1000.0;
        String figure = String.format("%.2f / %.2f / %.1f ms", h.getValueAtPercentile(50) / 1000.0, p99,
                h.getMaxValue() / 1000.0);
        boolean overTcp = !how.equals("in-process");
        report.check("[4] query " + how + ", " + when + ": p50 / p99 / max",
                overTcp ? figure + " (baseline, the same query in-process just before: " + inProcessFigure + ")" : figure,
                String.format("p99 <= %.0f ms", targetMs), p99 <= targetMs);
        if (!overTcp) {
            inProcessFigure = figure;
        }
    }

    private Thread heapSampler() {
        Thread t = new Thread(() -> {
            while (!Thread.currentThread().isInterrupted()) {
                long used = ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
                peakHeap.accumulateAndGet(used, Math::max);
                try {
                    Thread.sleep(100);
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "bench-heap-sampler");
        t.setDaemon(true);
        t.start();
        return t;
    }

    private static long nowMicros() {
        java.time.Instant now = java.time.Instant.now();
        return now.getEpochSecond() * 1_000_000L + now.getNano() / 1_000L;
    }

    private static long gcCount() {
        long total = 0;
        for (var gc : ManagementFactory.getGarbageCollectorMXBeans()) {
            total += Math.max(0, gc.getCollectionCount());
        }
        return total;
    }

    /** Where the tail goes: how many queries took longer than the target, and how many of those spanned a collection. */
    private static final class SlowQueries {
        private final long targetMicros;
        private int over;
        private int overWithGc;
        private int total;

        SlowQueries(double targetMs) {
            targetMicros = Math.round(targetMs * 1000);
        }

        void add(long micros, boolean collected) {
            total++;
            if (micros > targetMicros) {
                over++;
                if (collected) {
                    overWithGc++;
                }
            }
        }

        @Override
        public String toString() {
            return String.format("%d of %d queries over %.1f ms, %d of them spanned a collection in this JVM (the rest:"
                    + " scheduling, safepoints)", over, total, targetMicros / 1000.0, overWithGc);
        }
    }

    private static long gcMillis() {
        long total = 0;
        for (var gc : ManagementFactory.getGarbageCollectorMXBeans()) {
            total += Math.max(0, gc.getCollectionTime());
        }
        return total;
    }

    private static String show(DatabaseTarget target, String setting) throws SQLException {
        try (Connection c = target.open(); Statement s = c.createStatement(); ResultSet rs = s.executeQuery("SHOW " + setting)) {
            rs.next();
            return rs.getString(1);
        }
    }

    private static long count(DatabaseTarget target, String sql) throws SQLException {
        try (Connection c = target.open(); Statement s = c.createStatement(); ResultSet rs = s.executeQuery(sql)) {
            rs.next();
            return rs.getLong(1);
        }
    }
}

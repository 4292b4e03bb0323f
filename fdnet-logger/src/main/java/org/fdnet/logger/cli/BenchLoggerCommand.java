package org.fdnet.logger.cli;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.lang.management.ManagementFactory;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.Callable;
import org.HdrHistogram.Histogram;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.ValueType;
import org.fdnet.event.client.ViewerClient;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.cache.CachedEvent;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.cache.MonitorSubscriber;
import org.fdnet.logger.cache.RunProgress;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.logger.store.EmbeddedDatabase;
import org.fdnet.logger.store.SourceDirectory;
import org.postgresql.PGConnection;
import org.postgresql.copy.CopyIn;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code fdnet bench logger}: a separate producer process (the real core client) → logger → PostgreSQL,
 * beside its baseline measured in the same run on the same database: raw COPY of the same rows into the
 * same table, in batches of the same size each sorted by (sourceid, time), one commit per batch. Then the
 * burst (events taken into the cache while the writer drains) and a viewer's query answered from the cache.
 */
@Command(name = "logger", mixinStandardHelpOptions = true,
        description = "Benchmark the logger against raw COPY (same run, same database).")
public final class BenchLoggerCommand implements Callable<Integer> {
    @Option(names = "--events", defaultValue = "100000000", description = "events the producer sends at most (default 100,000,000: --seconds decides)")
    long events;

    @Option(names = "--seconds", defaultValue = "60", description = "producer runs at most this long (default 60)")
    long seconds;

    @Option(names = "--batch", defaultValue = "1000", description = "writer batch size = baseline batch size (default 1000)")
    int batch;

    @Option(names = "--nodes", defaultValue = "100", description = "Data nodes the producer writes (default 100)")
    int nodes;

    @Option(names = "--burst", defaultValue = "5000000", description = "events of the burst (default 5,000,000)")
    int burst;

    @Option(names = "--db", description = "external database jdbc:postgresql://... (default: a fresh embedded one)")
    String db;

    private long peakHeap;

    @Override
    public Integer call() throws Exception {
        Path dir = Files.createTempDirectory("fdnet-bench-logger");
        EmbeddedDatabase embedded = db == null ? EmbeddedDatabase.startThrowaway(dir.resolve("pg")) : null;
        DatabaseTarget target = embedded != null ? embedded.target() : new DatabaseTarget(db, "postgres", "");
        try {
            System.out.printf("fdnet bench logger: %,d events max, %d s max, batch %d, %d nodes, database %s%n",
                    events, seconds, batch, nodes, target.url());
            LoggerConfig config = new LoggerConfig()
                    .set(LoggerSetting.DATABASE_EMBEDDED, "false").set(LoggerSetting.DATABASE_URL, target.url())
                    .set(LoggerSetting.DATABASE_USER, target.user())
                    .set(LoggerSetting.WRITER_BATCH_SIZE, Integer.toString(batch))
                    .set(LoggerSetting.RECEIVER_PORT, "0").set(LoggerSetting.SENDER_PORT, "0")
                    .set(LoggerSetting.MEMORY_CAPACITY_MB, "1536").set(LoggerSetting.PRIORITY_CRITICAL, "90");
            try (NetworkStateLogger logger = new NetworkStateLogger(config)) {
                logger.start();
                SustainedResult sustained = sustained(logger, target);
                double baseline = baseline(target, sustained.stored);
                System.out.printf("baseline raw COPY: %,.0f rows/s (%,d rows, batches of %d sorted by (sourceid, time), "
                        + "one commit each)%n", baseline, sustained.stored, batch);
                System.out.printf("RATIO logger/raw COPY = %.2f sustained (%.2f over the whole run incl. warm-up; target >= 0.80)%n",
                        sustained.rate / baseline, sustained.whole / baseline);
                burstAndQuery(logger);
            }
            System.out.printf("peak heap (logger JVM): %,d MiB%n", peakHeap >> 20);
            return 0;
        } finally {
            if (embedded != null) {
                embedded.close();
            }
            Files.deleteIfExists(dir);
        }
    }

    private record SustainedResult(long stored, double rate, double whole) {
    }

    private SustainedResult sustained(NetworkStateLogger logger, DatabaseTarget target) throws Exception {
        List<String> cmd = List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx1g",
                "-cp", System.getProperty("java.class.path"), BenchProducer.class.getName(), "127.0.0.1",
                Integer.toString(logger.receiverPort()), Long.toString(events), Long.toString(seconds),
                Integer.toString(nodes));
        Process producer = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        List<String> output = new ArrayList<>();
        Thread reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(producer.getInputStream(), StandardCharsets.UTF_8))) {
                String line;
                while ((line = r.readLine()) != null) {
                    synchronized (output) {
                        output.add(line);
                    }
                }
            } catch (java.io.IOException e) {
                output.add("reader: " + e.getMessage());
            }
        });
        reader.start();
        EventCache cache = logger.cache();
        long firstCommit = 0;
        long lastChange = 0;
        long lastCount = 0;
        long nextReport = System.nanoTime() + 5_000_000_000L;
        long warmNanos = 0;
        long warmCount = 0;
        while (producer.isAlive()) {
            Thread.sleep(50);
            if (System.nanoTime() > nextReport) {
                nextReport += 5_000_000_000L;
                var st = cache.status();
                if (warmNanos == 0) {
                    warmNanos = System.nanoTime();
                    warmCount = st.committed();
                }
                System.out.printf("  ... received %,d, committed %,d, unwritten %,d, cache %.0f%%%s%n", st.received(),
                        st.committed(), st.unwritten(), st.usedPercent(), st.pressured() ? " (pressured)" : "");
            }
            sampleHeap();
            long c = cache.committedCount();
            if (c > 0 && firstCommit == 0) {
                firstCommit = System.nanoTime();
            }
            if (c != lastCount) {
                lastCount = c;
                lastChange = System.nanoTime();
            }
        }
        reader.join();
        long accepted = -1;
        long lost = -1;
        for (String line : output) {
            if (line.startsWith("accepted ")) {
                String[] p = line.split(" ");
                accepted = Long.parseLong(p[1]);
                lost = Long.parseLong(p[3]);
            }
        }
        if (producer.exitValue() != 0 || accepted < 0) {
            throw new IllegalStateException("producer failed: " + String.join("\n", output));
        }
        long stored = count(target, "SELECT count(*) FROM datavalue_log");
        long names = count(target, "SELECT count(*) FROM fdnet_node WHERE node IS NOT NULL");
        double seconds = (lastChange - firstCommit) / 1e9;
        double whole = stored / seconds;
        double rate = warmNanos == 0 || lastChange <= warmNanos ? whole
                : (lastCount - warmCount) / ((lastChange - warmNanos) / 1e9);
        System.out.printf("logger: %,d events stored in %.1f s (first to last commit) = %,.0f events/s over the whole run;"
                + " %,.0f events/s sustained after the first 5 s (JIT warm-up)%n", stored, seconds, whole, rate);
        System.out.printf("loss counted in the database: accepted by the client %,d (values %,d + names %d), stored %,d + %d"
                + " names -> %,d missing; client-side losses %d%n", accepted, accepted - nodes, nodes, stored, names,
                accepted - stored - names, lost);
        return new SustainedResult(stored, rate, whole);
    }

    private void sampleHeap() {
        long used = ManagementFactory.getMemoryMXBean().getHeapMemoryUsage().getUsed();
        peakHeap = Math.max(peakHeap, used);
    }

    private double baseline(DatabaseTarget target, long rows) throws SQLException {
        try (Connection c = target.open(); Statement s = c.createStatement()) {
            s.execute("CREATE TABLE bench_baseline (LIKE datavalue_log INCLUDING ALL)");
            c.setAutoCommit(false);
            long t0 = System.nanoTime();
            long time = System.currentTimeMillis() * 1000;
            long[] keys = new long[batch];
            StringBuilder sb = new StringBuilder(batch * 40);
            for (long done = 0; done < rows; ) {
                int n = (int) Math.min(batch, rows - done);
                for (int i = 0; i < n; i++) {
                    keys[i] = ((done + i) % nodes) << 40 | (i);
                }
                java.util.Arrays.sort(keys, 0, n);
                sb.setLength(0);
                for (int i = 0; i < n; i++) {
                    long node = keys[i] >>> 40;
                    long idx = keys[i] & ((1L << 40) - 1);
                    sb.append(node + 1).append('\t').append(time + done + idx).append('\t')
                            .append(Double.toString((done + idx) * 0.001)).append('\t').append(ValueType.DOUBLE.code()).append('\n');
                }
                byte[] bytes = sb.toString().getBytes(StandardCharsets.UTF_8);
                CopyIn in = c.unwrap(PGConnection.class).getCopyAPI().copyIn("COPY bench_baseline (sourceid, time, value, typevalue) FROM STDIN");
                in.writeToCopy(bytes, 0, bytes.length);
                in.endCopy();
                c.commit();
                done += n;
            }
            double rate = rows / ((System.nanoTime() - t0) / 1e9);
            c.setAutoCommit(true);
            s.execute("DROP TABLE bench_baseline");
            return rate;
        }
    }

    private void burstAndQuery(NetworkStateLogger logger) throws Exception {
        EventCache cache = logger.cache();
        long maxByHeap = (Runtime.getRuntime().maxMemory() - (512L << 20)) / 300;
        int n = (int) Math.min(burst, maxByHeap);
        if (n < burst) {
            System.out.printf("burst reduced to %,d events: the heap (%d MiB) is too small; use FDNET_JAVA_OPTS=-Xmx4g%n",
                    n, Runtime.getRuntime().maxMemory() >> 20);
        }
        var directory = logger.directory();
        RunProgress run = directory.openRun(UUID.randomUUID(), "bench-burst");
        int burstNodes = 1000;
        int[] ids = new int[burstNodes];
        for (int i = 0; i < burstNodes; i++) {
            ids[i] = directory.globalId(run, i);
        }
        long time = System.currentTimeMillis() * 1000;
        List<CachedEvent> held = new ArrayList<>();
        MonitorSubscriber monitor = held::add;
        cache.subscribe(monitor, new int[] {ids[7]});
        List<CachedEvent> chunk = new ArrayList<>(2048);
        long committedBefore = cache.committedCount();
        long t0 = System.nanoTime();
        for (int i = 0; i < n; i++) {
            DataValueEvent e = new DataValueEvent(ids[i % burstNodes], time + i, ValueType.DOUBLE, "0.5");
            chunk.add(new CachedEvent(e, run, i + 1, cache.sizeOf(e), System.nanoTime()));
            if (chunk.size() == 2048) {
                cache.add(chunk);
                chunk = new ArrayList<>(2048);
            }
        }
        cache.add(chunk);
        double seconds = (System.nanoTime() - t0) / 1e9;
        sampleHeap();
        System.out.printf("burst: %,d events into the cache in %.2f s = %,.0f events/s (target >= 1,000,000);"
                + " the writer committed %,d meanwhile%n", n, seconds, n / seconds, cache.committedCount() - committedBefore);
        // "The last 10 s of one node": the burst's times are one microsecond apart, so one node's last 10 s
        // are the events of the last 10,000,000 us of the burst (all of them when the burst is shorter). A
        // viewer monitors that node, as one plotting it would: its events stay in memory after their commit.
        int node = ids[7];
        long to = time + n;
        long from = to - 10_000_000;
        long deadline = System.nanoTime() + 120_000_000_000L;
        queries("while the writer drains", cache, directory, node, from, to);
        while (cache.unwrittenCount() > 0 && System.nanoTime() < deadline) {
            Thread.sleep(100);
        }
        queries("after the drain, writer idle", cache, directory, node, from, to);
        Histogram overTcp = new Histogram(3);
        try (ViewerClient viewer = new ViewerClient("127.0.0.1", logger.senderPort(), "bench", e -> { })) {
            int got = 0;
            for (int i = 0; i < 500; i++) {
                long q0 = System.nanoTime();
                got = viewer.history(new int[] {node}, from, to).size();
                overTcp.recordValue((System.nanoTime() - q0) / 1000);
            }
            System.out.printf("the same query through a ViewerClient over TCP, after the drain (%,d events decoded):"
                    + " p50 %d us, p99 %d us%n", got, overTcp.getValueAtPercentile(50), overTcp.getValueAtPercentile(99));
        }
        cache.unsubscribe(monitor, new int[] {node}, held);
        sampleHeap();
        System.out.println("stopping: the writer drains the burst into the database ...");
    }

    private static void queries(String when, EventCache cache, SourceDirectory directory, int node, long from, long to) {
        Histogram h = new Histogram(3);
        long gcBefore = gcMillis();
        int found = 0;
        boolean complete = true;
        for (int i = 0; i < 2000; i++) {
            long q0 = System.nanoTime();
            EventCache.CacheAnswer a = cache.history(node, from, to, directory.seenFromStart(node));
            h.recordValue((System.nanoTime() - q0) / 1000);
            found = a.events().size();
            complete &= a.complete();
        }
        System.out.printf("viewer query, last 10 s of one monitored node from the cache (%,d events%s), 2,000 queries %s:"
                        + " in-process p50 %d us, p99 %d us, max %d us (target p99 <= 1 ms); GC meanwhile %d ms%n", found,
                complete ? ", cache complete" : ", CACHE INCOMPLETE", when, h.getValueAtPercentile(50),
                h.getValueAtPercentile(99), h.getMaxValue(), gcMillis() - gcBefore);
    }

    private static long gcMillis() {
        long total = 0;
        for (var gc : ManagementFactory.getGarbageCollectorMXBeans()) {
            total += Math.max(0, gc.getCollectionTime());
        }
        return total;
    }

    private static long count(DatabaseTarget target, String sql) throws SQLException {
        try (Connection c = target.open(); Statement s = c.createStatement(); ResultSet rs = s.executeQuery(sql)) {
            rs.next();
            return rs.getLong(1);
        }
    }
}

package org.fdnet.logger.bench;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.sql.Connection;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import org.fdnet.event.ValueType;
import org.fdnet.logger.store.BackendNiceness;
import org.fdnet.logger.store.DatabaseTarget;
import org.postgresql.PGConnection;
import org.postgresql.copy.CopyIn;

/**
 * The logger's baseline: raw COPY of rows like the benchmark's (same nodes, same kind of values) into a fresh
 * table defined as {@code datavalue_log} ({@code LIKE ... INCLUDING ALL}: same primary key), batch after
 * batch of the given sizes, each batch sorted by (sourceid, time) and committed on its own, from one thread —
 * or, like the writer with several connections, pipelined over several connections with the commits in batch
 * order ({@link #runPipelined}). No cache, no network, no watermark: what PostgreSQL alone takes.
 */
final class RawCopyBaseline {
    /** How the rows are sent: PostgreSQL's text or binary COPY format. */
    enum Format { TEXT, BINARY }

    private static final byte[] BINARY_HEADER = {'P', 'G', 'C', 'O', 'P', 'Y', '\n', (byte) 0xff, '\r', '\n', 0, 0, 0, 0,
            0, 0, 0, 0, 0};

    private final DatabaseTarget target;
    private final int nodes;
    private final BackendNiceness backends;
    private final int threadPriority;

    /**
     * @param backendNiceness and
     * @param threadPriority  the writer's: the baseline's backends and COPY threads run at the priorities the
     *                        logger's writer runs at, so that on a loaded machine the ratio still compares like
     *                        with like
     */
    RawCopyBaseline(DatabaseTarget target, int nodes, int backendNiceness, int threadPriority) {
        this.target = target;
        this.nodes = nodes;
        this.backends = new BackendNiceness(backendNiceness);
        this.threadPriority = threadPriority;
    }

    /** Rows per second for {@code rows} rows cut into batches of {@code sizes} (the last size repeats). */
    double run(long rows, int[] sizes, Format format) throws SQLException {
        int callerPriority = Thread.currentThread().getPriority();
        try (Connection c = target.open(); Statement s = c.createStatement()) {
            freshBaselineTable(s);
            backends.apply(c);
            Thread.currentThread().setPriority(threadPriority);
            long t0 = System.nanoTime();
            copy(c, rows, sizes, format, 0, 1);
            double rate = rows / ((System.nanoTime() - t0) / 1e9);
            s.execute("DROP TABLE bench_baseline");
            return rate;
        } finally {
            Thread.currentThread().setPriority(callerPriority);
        }
    }

    /**
     * Rows per second for the same rows and batches as {@link #run} (text format), sent the way the writer
     * sends them with {@code connections} connections: batch i on connection i mod {@code connections}, each
     * COPYed as soon as its connection is free, committed only after batch i - 1 committed. The like-for-like
     * baseline of a writer with that many connections.
     */
    double runPipelined(long rows, int[] sizes, int connections) throws SQLException, InterruptedException {
        List<long[]> plan = new ArrayList<>(); // {first row, rows} of each batch
        for (long done = 0; done < rows; ) {
            int n = (int) Math.min(sizes[Math.min(plan.size(), sizes.length - 1)], rows - done);
            plan.add(new long[] {done, n});
            done += n;
        }
        try (Connection c = target.open(); Statement s = c.createStatement()) {
            freshBaselineTable(s);
            List<Connection> open = new ArrayList<>();
            try {
                openConnections(open, connections, false);
                CommitTurn turn = new CommitTurn();
                AtomicReference<Exception> failure = new AtomicReference<>();
                List<Thread> threads = new ArrayList<>();
                long time = System.currentTimeMillis() * 1000;
                long t0 = System.nanoTime();
                for (int i = 0; i < connections; i++) {
                    Connection mine = open.get(i);
                    int first = i;
                    Thread t = new Thread(() -> {
                        try {
                            long[] keys = new long[Arrays.stream(sizes).max().orElse(1)];
                            for (int b = first; b < plan.size(); b += connections) {
                                long done = plan.get(b)[0];
                                int n = (int) plan.get(b)[1];
                                for (int k = 0; k < n; k++) {
                                    keys[k] = ((done + k) % nodes) << 40 | k;
                                }
                                Arrays.sort(keys, 0, n);
                                byte[] bytes = text(keys, n, done, time);
                                CopyIn in = mine.unwrap(PGConnection.class).getCopyAPI()
                                        .copyIn("COPY bench_baseline (sourceid, time, value, typevalue) FROM STDIN");
                                in.writeToCopy(bytes, 0, bytes.length);
                                in.endCopy();
                                turn.await(b);
                                mine.commit();
                                turn.committed(b);
                            }
                        } catch (SQLException | InterruptedException e) {
                            failure.compareAndSet(null, e);
                            turn.fail();
                        }
                    }, "bench-pipelined-copy-" + i);
                    t.setPriority(threadPriority);
                    threads.add(t);
                    t.start();
                }
                for (Thread t : threads) {
                    t.join();
                }
                double rate = rows / ((System.nanoTime() - t0) / 1e9);
                if (failure.get() instanceof SQLException e) {
                    throw e;
                } else if (failure.get() != null) {
                    throw new SQLException("pipelined COPY interrupted", failure.get());
                }
                s.execute("DROP TABLE bench_baseline");
                return rate;
            } finally {
                for (Connection o : open) {
                    o.close();
                }
            }
        }
    }

    /** Whose COMMIT is next: batch i commits after batch i - 1 (or gives up when another thread failed). */
    private static final class CommitTurn {
        private int next;
        private boolean failed;

        synchronized void await(int batch) throws InterruptedException, SQLException {
            while (next != batch && !failed) {
                wait();
            }
            if (failed) {
                throw new SQLException("another connection of the pipelined baseline failed");
            }
        }

        synchronized void committed(int batch) {
            next = batch + 1;
            notifyAll();
        }

        synchronized void fail() {
            failed = true;
            notifyAll();
        }
    }

    /**
     * Rows per second when {@code connections} connections COPY at once, each its own share of the nodes
     * (disjoint key ranges) in sorted batches of {@code batch} rows, each committing its own batches: what
     * PostgreSQL takes when more than one backend works on the table.
     */
    double runParallel(long rows, int batch, int connections) throws SQLException, InterruptedException {
        try (Connection c = target.open(); Statement s = c.createStatement()) {
            freshBaselineTable(s);
            List<Connection> open = new ArrayList<>();
            try {
                openConnections(open, connections, true);
                AtomicReference<SQLException> failure = new AtomicReference<>();
                List<Thread> threads = new ArrayList<>();
                long t0 = System.nanoTime();
                for (int i = 0; i < connections; i++) {
                    Connection mine = open.get(i);
                    int part = i;
                    Thread t = new Thread(() -> {
                        try {
                            copy(mine, rows / connections, new int[] {batch}, Format.TEXT, part, connections);
                        } catch (SQLException e) {
                            failure.compareAndSet(null, e);
                        }
                    }, "bench-copy-" + i);
                    t.setPriority(threadPriority);
                    threads.add(t);
                    t.start();
                }
                for (Thread t : threads) {
                    t.join();
                }
                double rate = (rows / connections * connections) / ((System.nanoTime() - t0) / 1e9);
                if (failure.get() != null) {
                    throw failure.get();
                }
                s.execute("DROP TABLE bench_baseline");
                return rate;
            } finally {
                for (Connection o : open) {
                    o.close();
                }
            }
        }
    }

    /** COPYs {@code rows} rows of the nodes {@code part, part + parts, ...} in sorted, committed batches. */
    private void copy(Connection c, long rows, int[] sizes, Format format, int part, int parts) throws SQLException {
        c.setAutoCommit(false);
        long time = System.currentTimeMillis() * 1000;
        int largest = Arrays.stream(sizes).max().orElse(1);
        long[] keys = new long[largest];
        int myNodes = Math.max(1, nodes / parts);
        String sql = "COPY bench_baseline (sourceid, time, value, typevalue) FROM STDIN"
                + (format == Format.BINARY ? " (FORMAT binary)" : "");
        int b = 0;
        for (long done = 0; done < rows; ) {
            int n = (int) Math.min(sizes[Math.min(b++, sizes.length - 1)], rows - done);
            for (int i = 0; i < n; i++) {
                keys[i] = (((done + i) % myNodes) * parts + part) << 40 | i;
            }
            Arrays.sort(keys, 0, n);
            byte[] bytes = format == Format.BINARY ? binary(keys, n, done, time) : text(keys, n, done, time);
            CopyIn in = c.unwrap(PGConnection.class).getCopyAPI().copyIn(sql);
            in.writeToCopy(bytes, 0, bytes.length);
            in.endCopy();
            c.commit();
            done += n;
        }
        c.setAutoCommit(true);
    }

    private static byte[] text(long[] keys, int n, long done, long time) {
        StringBuilder sb = new StringBuilder(n * 40);
        for (int i = 0; i < n; i++) {
            long node = keys[i] >>> 40;
            long idx = keys[i] & ((1L << 40) - 1);
            sb.append(node + 1).append('\t').append(time + done + idx).append('\t')
                    .append(Double.toString((done + idx) * 0.001)).append('\t').append(ValueType.DOUBLE.code()).append('\n');
        }
        return sb.toString().getBytes(StandardCharsets.UTF_8);
    }

    private static byte[] binary(long[] keys, int n, long done, long time) {
        ByteArrayOutputStream bytes = new ByteArrayOutputStream(n * 48 + 32);
        try (DataOutputStream out = new DataOutputStream(bytes)) {
            out.write(BINARY_HEADER);
            for (int i = 0; i < n; i++) {
                long node = keys[i] >>> 40;
                long idx = keys[i] & ((1L << 40) - 1);
                byte[] value = Double.toString((done + idx) * 0.001).getBytes(StandardCharsets.UTF_8);
                out.writeShort(4);
                out.writeInt(4);
                out.writeInt((int) node + 1);
                out.writeInt(8);
                out.writeLong(time + done + idx);
                out.writeInt(value.length);
                out.write(value);
                out.writeInt(2);
                out.writeShort(ValueType.DOUBLE.code());
            }
            out.writeShort(-1);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return bytes.toByteArray();
    }

    /** The baseline's table, empty, with the same definition (and primary key) as {@code datavalue_log}. */
    private static void freshBaselineTable(Statement s) throws SQLException {
        s.execute("DROP TABLE IF EXISTS bench_baseline");
        s.execute("CREATE TABLE bench_baseline (LIKE datavalue_log INCLUDING ALL)");
    }

    /** Opens {@code n} connections into {@code open} (the caller closes them, also after a failure). */
    private void openConnections(List<Connection> open, int n, boolean autoCommit) throws SQLException {
        for (int i = 0; i < n; i++) {
            Connection o = target.open();
            open.add(o);
            backends.apply(o);
            o.setAutoCommit(autoCommit);
        }
    }
}

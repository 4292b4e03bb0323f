package org.fdnet.logger.cli;

import java.io.ByteArrayOutputStream;
import java.io.DataOutputStream;
import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.sql.Connection;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.Arrays;
import org.fdnet.event.ValueType;
import org.fdnet.logger.store.DatabaseTarget;
import org.postgresql.PGConnection;
import org.postgresql.copy.CopyIn;

/**
 * The logger's baseline: raw COPY of rows like the benchmark's (same nodes, same kind of values) into a fresh
 * table defined as {@code datavalue_log} ({@code LIKE ... INCLUDING ALL}: same primary key), batch after
 * batch of the given sizes, each batch sorted by (sourceid, time) and committed on its own, from one thread.
 * No cache, no network, no watermark: what PostgreSQL alone takes.
 */
final class RawCopyBaseline {
    /** How the rows are sent: PostgreSQL's text or binary COPY format. */
    enum Format { TEXT, BINARY }

    private static final byte[] BINARY_HEADER = {'P', 'G', 'C', 'O', 'P', 'Y', '\n', (byte) 0xff, '\r', '\n', 0, 0, 0, 0,
            0, 0, 0, 0, 0};

    private final DatabaseTarget target;
    private final int nodes;

    RawCopyBaseline(DatabaseTarget target, int nodes) {
        this.target = target;
        this.nodes = nodes;
    }

    /** Rows per second for {@code rows} rows cut into batches of {@code sizes} (the last size repeats). */
    double run(long rows, int[] sizes, Format format) throws SQLException {
        try (Connection c = target.open(); Statement s = c.createStatement()) {
            s.execute("DROP TABLE IF EXISTS bench_baseline");
            s.execute("CREATE TABLE bench_baseline (LIKE datavalue_log INCLUDING ALL)");
            c.setAutoCommit(false);
            c.commit();
            long time = System.currentTimeMillis() * 1000;
            int largest = Arrays.stream(sizes).max().orElse(1);
            long[] keys = new long[largest];
            String sql = "COPY bench_baseline (sourceid, time, value, typevalue) FROM STDIN"
                    + (format == Format.BINARY ? " (FORMAT binary)" : "");
            long t0 = System.nanoTime();
            int b = 0;
            for (long done = 0; done < rows; ) {
                int n = (int) Math.min(sizes[Math.min(b++, sizes.length - 1)], rows - done);
                for (int i = 0; i < n; i++) {
                    keys[i] = ((done + i) % nodes) << 40 | i;
                }
                Arrays.sort(keys, 0, n);
                byte[] bytes = format == Format.BINARY ? binary(keys, n, done, time) : text(keys, n, done, time);
                CopyIn in = c.unwrap(PGConnection.class).getCopyAPI().copyIn(sql);
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
}

package org.fdnet.logger.store;

import java.sql.Array;
import java.sql.Connection;
import org.fdnet.event.RunIdentity;
import org.fdnet.event.wire.LoggedRun;
import org.fdnet.event.wire.RunFrame;
import java.sql.PreparedStatement;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.UUID;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkCommand;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.event.TypedValue;
import org.fdnet.event.ValueType;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.logger.cache.CachedEvent;
import org.fdnet.logger.cache.RunProgress;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.postgresql.PGConnection;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;
import org.postgresql.copy.CopyIn;
import org.postgresql.copy.CopyManager;

/**
 * The logger's tables in PostgreSQL. {@link #writeBatch} is the writer's path: one transaction per batch,
 * new node mappings and names first, then COPY of the values sorted by {@code (sourceid, time)} (the
 * primary key's order: the B-tree is the bottleneck and sorted input halves its cost), then each run's
 * committed sequence number. The other methods serve handshakes and viewers from a small pool.
 */
public final class EventStore implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(EventStore.class);
    private static final Comparator<CachedEvent> KEY_ORDER =
            Comparator.comparingInt(CachedEvent::sourceId).thenComparingLong(CachedEvent::time);

    private final DatabaseTarget target;
    private final ConnectionPool pool;
    /** How long a writer's statement waits for a lock before it fails (then its batch is rolled back and retried in order). */
    public static final int WRITER_LOCK_TIMEOUT_MILLIS = 5000;
    /** One COPY buffer per writer thread: with several writer connections, batches are encoded at once. */
    private final ThreadLocal<CopyRows> copyRows = ThreadLocal.withInitial(CopyRows::new);

    /**
     * Rows built and sent per COPY chunk: between two chunks the writer yields to viewer queries
     * ({@link QueryPriority}). Small enough that what the backend still has to read when the writer pauses is a
     * few milliseconds of its work (it takes 200,000-400,000 rows/s), large enough that a chunk is tens of
     * kilobytes (the driver sends in 8 KiB writes anyway).
     */
    static final int COPY_CHUNK_ROWS = 1024;
    private final QueryPriority queries;
    private final BackendNiceness writerBackends;

    public EventStore(DatabaseTarget target) {
        this(target, new QueryPriority(0), 0); // no viewers: never pauses, backends untouched
    }

    /**
     * A store whose writers pause between COPY chunks while {@code queries} says a viewer's query is answered, and
     * whose writer backends run at {@code writerBackendNiceness} when the database is on this host
     * ({@link BackendNiceness}; 0 leaves them alone).
     */
    public EventStore(DatabaseTarget target, QueryPriority queries, int writerBackendNiceness) {
        this.target = target;
        this.pool = new ConnectionPool(target, 8);
        this.queries = queries;
        this.writerBackends = new BackendNiceness(writerBackendNiceness);
    }

    public DatabaseTarget target() {
        return target;
    }

    /** Creates the tables if they are missing. */
    public void createSchema() throws SQLException {
        try (Connection c = target.open()) {
            Schema.create(c);
        }
    }

    /**
     * A connection for the writer (auto-commit off), its backend at the writer's nice value, with a lock timeout: two writer transactions in flight
     * could otherwise wait for each other where PostgreSQL cannot see it (the later one waits for the earlier
     * one's commit in the client); a lock wait beyond {@link #WRITER_LOCK_TIMEOUT_MILLIS} fails the statement.
     */
    public Connection openWriterConnection() throws SQLException {
        Connection c = target.open();
        try (Statement st = c.createStatement()) {
            st.execute("SET lock_timeout = " + WRITER_LOCK_TIMEOUT_MILLIS);
        } catch (SQLException e) {
            c.close();
            throw e;
        }
        writerBackends.apply(c);
        c.setAutoCommit(false);
        return c;
    }

    /**
     * A batch COPYed in a transaction still open on its connection: what {@link #commitBatch} needs to write
     * the runs' watermarks and commit. The highest sequence number of each run in the batch.
     */
    public static final class OpenBatch {
        private final Map<RunProgress, Long> lastSeq;

        private OpenBatch(Map<RunProgress, Long> lastSeq) {
            this.lastSeq = lastSeq;
        }
    }

    /**
     * Writes one batch in one transaction on the writer's connection. On failure the transaction is rolled
     * back (if the connection still answers) and the exception is rethrown: nothing of the batch is stored.
     */
    public void writeBatch(Connection c, List<CachedEvent> batch, List<NodeMapping> mappings) throws SQLException {
        commitBatch(c, copyBatch(c, batch, mappings));
    }

    /**
     * The first part of {@link #writeBatch}: in a new transaction, the mappings, the names, then COPY of the
     * values sorted by key; the transaction stays open for {@link #commitBatch} or {@link #rollback}. On
     * failure it is rolled back and the exception rethrown.
     */
    public OpenBatch copyBatch(Connection c, List<CachedEvent> batch, List<NodeMapping> mappings) throws SQLException {
        List<CachedEvent> data = new ArrayList<>();
        List<CachedEvent> relations = new ArrayList<>();
        List<CachedEvent> commands = new ArrayList<>();
        List<CachedEvent> names = new ArrayList<>();
        for (CachedEvent e : batch) {
            NetworkEvent ev = e.event();
            if (ev instanceof DataValueEvent) {
                data.add(e);
            } else if (ev instanceof RelationValueEvent) {
                relations.add(e);
            } else if (ev instanceof NetworkCommandEvent) {
                commands.add(e);
            } else {
                names.add(e);
            }
        }
        Map<RunProgress, Long> lastSeq = lastSeqByRun(batch);
        CopyRows rows = copyRows.get();
        try {
            saveMappings(c, mappings);
            saveNames(c, names);
            CopyManager copy = c.unwrap(PGConnection.class).getCopyAPI();
            sortByKey(data);
            copyInChunks(copy, rows, data, "COPY datavalue_log (sourceid, time, value, typevalue) FROM STDIN", e -> {
                DataValueEvent d = (DataValueEvent) e;
                rows.number(d.sourceId()).number(d.time()).value(d.value()).number(d.type().code()).endRow();
            });
            sortByKey(relations);
            copyInChunks(copy, rows, relations, "COPY procvalue_log (sourceid, time, value) FROM STDIN", e -> {
                RelationValueEvent r = (RelationValueEvent) e;
                rows.number(r.sourceId()).number(r.time()).text(r.value()).endRow();
            });
            rows.clear();
            for (CachedEvent e : commands) {
                NetworkCommandEvent n = (NetworkCommandEvent) e.event();
                rows.number(n.sourceId()).text(n.sourceType()).text(n.command().text()).text(n.paramsId())
                        .text(n.paramsType()).number(n.time()).endRow();
            }
            copy(copy, rows, "COPY netcommand_log (sourceid, sourcetype, command, params_id, params_type, time) FROM STDIN");
        } catch (SQLException | RuntimeException e) {
            rollbackQuietly(c, e);
            throw e;
        }
        return new OpenBatch(lastSeq);
    }

    /**
     * The second part of {@link #writeBatch}: each run's committed sequence number and the COMMIT, in one
     * round trip; then the runs' cores are told (ACK). On failure the transaction is rolled back (if the
     * connection still answers) and the exception rethrown — when the COMMIT itself was lost on the way, the
     * outcome is unknown: ask {@link #wasCommitted}.
     */
    public void commitBatch(Connection c, OpenBatch open) throws SQLException {
        try {
            // The watermarks and the COMMIT go in one round trip: the statements are integers only.
            StringBuilder sql = new StringBuilder();
            for (Map.Entry<RunProgress, Long> r : open.lastSeq.entrySet()) {
                sql.append("UPDATE fdnet_run SET committed_seq = ").append(r.getValue()).append(" WHERE run_id = ")
                        .append(r.getKey().runId()).append(" AND committed_seq < ").append(r.getValue()).append("; ");
            }
            sql.append("COMMIT");
            try (Statement st = c.createStatement()) {
                st.execute(sql.toString());
            }
            c.commit(); // a no-op when the COMMIT above ended the transaction; commits otherwise
        } catch (SQLException | RuntimeException e) {
            rollbackQuietly(c, e);
            throw e;
        }
        for (Map.Entry<RunProgress, Long> r : open.lastSeq.entrySet()) {
            r.getKey().committed(r.getValue());
        }
    }

    /** Abandons a batch COPYed by {@link #copyBatch} (the batch before it failed): nothing of it is stored. */
    public void rollback(Connection c) throws SQLException {
        c.rollback();
    }

    /**
     * Sorts by (sourceid, time). A source's events arrive in time order, so a stable sort by source alone
     * (primitive keys: source id, then arrival index) is the key order; a late event (out of time order
     * within its source) makes it fall back to the full comparison.
     */
    static void sortByKey(List<CachedEvent> events) {
        int n = events.size();
        long[] keys = new long[n];
        for (int i = 0; i < n; i++) {
            keys[i] = (long) events.get(i).sourceId() << 32 | i;
        }
        java.util.Arrays.sort(keys);
        CachedEvent[] sorted = new CachedEvent[n];
        for (int i = 0; i < n; i++) {
            sorted[i] = events.get((int) keys[i]);
            if (i > 0 && sorted[i].sourceId() == sorted[i - 1].sourceId() && sorted[i].time() < sorted[i - 1].time()) {
                events.sort(KEY_ORDER);
                return;
            }
        }
        for (int i = 0; i < n; i++) {
            events.set(i, sorted[i]);
        }
    }

    /**
     * After a failure whose outcome is unknown (the connection died around the COMMIT): was the batch
     * committed? Its runs' watermarks were updated in the same transaction, so the database knows.
     */
    public boolean wasCommitted(List<CachedEvent> batch) throws SQLException {
        Map<RunProgress, Long> lastSeq = lastSeqByRun(batch);
        for (Map.Entry<RunProgress, Long> r : lastSeq.entrySet()) {
            List<Long> stored = query("SELECT committed_seq FROM fdnet_run WHERE run_id = " + r.getKey().runId(),
                    rs -> rs.getLong(1));
            if (stored.isEmpty() || stored.get(0) < r.getValue()) {
                return false;
            }
        }
        for (Map.Entry<RunProgress, Long> r : lastSeq.entrySet()) {
            r.getKey().committed(r.getValue());
        }
        return true;
    }

    /**
     * Each run's highest sequence number in the batch. A batch holds long stretches of one run's events, so the
     * maximum is kept in a local and boxed into the map only where the run changes, not once per event.
     */
    static Map<RunProgress, Long> lastSeqByRun(List<CachedEvent> batch) {
        Map<RunProgress, Long> lastSeq = new HashMap<>();
        RunProgress run = null;
        long max = Long.MIN_VALUE;
        for (CachedEvent e : batch) {
            if (e.run() != run) {
                if (run != null) {
                    lastSeq.merge(run, max, Math::max);
                }
                run = e.run();
                max = e.seq();
            } else if (e.seq() > max) {
                max = e.seq();
            }
        }
        if (run != null) {
            lastSeq.merge(run, max, Math::max);
        }
        return lastSeq;
    }

    /** Appends one event's row to the COPY buffer. */
    @FunctionalInterface
    private interface Row {
        void put(NetworkEvent e);
    }

    /**
     * One COPY statement for {@code events}, built and sent {@link #COPY_CHUNK_ROWS} rows at a time, yielding to
     * viewer queries between chunks (the backend then has nothing to read and sleeps too).
     */
    private void copyInChunks(CopyManager copy, CopyRows rows, List<CachedEvent> events, String sql, Row row)
            throws SQLException {
        if (events.isEmpty()) {
            return;
        }
        CopyIn in = copy.copyIn(sql);
        try {
            for (int start = 0; start < events.size(); start += COPY_CHUNK_ROWS) {
                rows.clear();
                int end = Math.min(events.size(), start + COPY_CHUNK_ROWS);
                for (int i = start; i < end; i++) {
                    row.put(events.get(i).event());
                }
                in.writeToCopy(rows.bytes(), 0, rows.length());
                queries.yieldToQueries();
            }
            in.endCopy();
        } finally {
            if (in.isActive()) {
                in.cancelCopy();
            }
        }
    }

    private static void copy(CopyManager copy, CopyRows rows, String sql) throws SQLException {
        if (rows.isEmpty()) {
            return;
        }
        CopyIn in = copy.copyIn(sql);
        try {
            in.writeToCopy(rows.bytes(), 0, rows.length());
            in.endCopy();
        } finally {
            if (in.isActive()) {
                in.cancelCopy();
            }
        }
    }

    private static void saveMappings(Connection c, List<NodeMapping> mappings) throws SQLException {
        if (mappings.isEmpty()) {
            return;
        }
        try (PreparedStatement ps = c.prepareStatement("INSERT INTO fdnet_node (sourceid, run_id, local_id)"
                + " VALUES (?, ?, ?) ON CONFLICT (sourceid) DO NOTHING")) {
            for (NodeMapping m : mappings) {
                ps.setInt(1, m.sourceId());
                ps.setInt(2, m.runId());
                ps.setInt(3, m.localId());
                ps.addBatch();
            }
            ps.executeBatch();
        }
    }

    private static void saveNames(Connection c, List<CachedEvent> names) throws SQLException {
        if (names.isEmpty()) {
            return;
        }
        try (PreparedStatement ps = c.prepareStatement(
                "UPDATE fdnet_node SET kind = ?, module = ?, node = ?, named_at = ? WHERE sourceid = ?")) {
            for (CachedEvent e : names) {
                NodeNamedEvent n = (NodeNamedEvent) e.event();
                ps.setString(1, n.kind() == NodeKind.DATA ? "data" : "proc");
                ps.setString(2, n.name().module());
                ps.setString(3, n.name().node());
                ps.setLong(4, n.time());
                ps.setInt(5, n.sourceId());
                ps.addBatch();
            }
            ps.executeBatch();
        }
    }

    private static void rollbackQuietly(Connection c, Exception cause) {
        try {
            c.rollback();
        } catch (SQLException e) {
            cause.addSuppressed(e);
        }
    }

    /** A run row. */
    public record RunRow(int runId, long committedSeq) {
    }

    public RunRow openRun(UUID uuid, String coreName) throws SQLException {
        Connection c = pool.borrow();
        boolean broken = true;
        try (PreparedStatement ins = c.prepareStatement("INSERT INTO fdnet_run (run_uuid, core_name) VALUES (?, ?)"
                + " ON CONFLICT (run_uuid) DO NOTHING");
             PreparedStatement sel = c.prepareStatement("SELECT run_id, committed_seq FROM fdnet_run WHERE run_uuid = ?")) {
            ins.setObject(1, uuid);
            ins.setString(2, coreName);
            ins.executeUpdate();
            sel.setObject(1, uuid);
            try (ResultSet rs = sel.executeQuery()) {
                rs.next();
                RunRow row = new RunRow(rs.getInt(1), rs.getLong(2));
                broken = false;
                return row;
            }
        } finally {
            pool.giveBack(c, broken);
        }
    }

    /**
     * Files the stream {@code runId} under the network run {@code part.run()} (made on its first mention) as
     * host {@code part.host()}; saying it again changes nothing.
     */
    public void joinNetworkRun(int runId, RunFrame part) throws SQLException {
        RunIdentity r = part.run();
        Connection c = pool.borrow();
        boolean broken = true;
        try (PreparedStatement ins = c.prepareStatement("INSERT INTO fdnet_network_run (run_uuid, network, definition,"
                + " definition_sha256, started, hosts) VALUES (?, ?, ?, ?, ?, ?) ON CONFLICT (run_uuid) DO NOTHING");
             PreparedStatement upd = c.prepareStatement("UPDATE fdnet_run SET host = ?, clock_offset = ?, network_run_id ="
                     + " (SELECT network_run_id FROM fdnet_network_run WHERE run_uuid = ?) WHERE run_id = ?")) {
            ins.setObject(1, r.id());
            ins.setString(2, r.network());
            ins.setString(3, r.definition());
            ins.setString(4, r.sha256());
            ins.setLong(5, r.startedMicros());
            ins.setArray(6, c.createArrayOf("text", r.hosts().toArray()));
            ins.executeUpdate();
            upd.setString(1, part.host());
            upd.setLong(2, part.clockOffsetMicros());
            upd.setObject(3, r.id());
            upd.setInt(4, runId);
            upd.executeUpdate();
            broken = false;
        } finally {
            pool.giveBack(c, broken);
        }
    }

    /**
     * Every stream (fdnet_run row), oldest first, with its network run; a stream of schema 1 or of a core that
     * named no run stands for itself (network run 0, named by its core, started when first seen, one host).
     */
    public List<LoggedRun> loadRuns() throws SQLException {
        return query("SELECT r.run_id, coalesce(n.network_run_id, 0), coalesce(n.network, r.core_name),"
                + " coalesce(r.host, r.core_name), coalesce(n.started, (extract(epoch FROM r.first_seen) * 1000000)::bigint),"
                + " coalesce(cardinality(n.hosts), 1), r.clock_offset FROM fdnet_run r"
                + " LEFT JOIN fdnet_network_run n USING (network_run_id) ORDER BY r.run_id",
                rs -> new LoggedRun(rs.getInt(1), rs.getInt(2), rs.getString(3), rs.getString(4), rs.getLong(5),
                        rs.getInt(6), rs.getLong(7)));
    }

    public List<NodeMapping> loadMappings(int runId) throws SQLException {
        return query("SELECT sourceid, run_id, local_id FROM fdnet_node WHERE run_id = " + runId,
                rs -> new NodeMapping(rs.getInt(1), rs.getInt(2), rs.getInt(3)));
    }

    public List<LoggedNode> loadNodes() throws SQLException {
        return query("SELECT sourceid, run_id, kind, module, node FROM fdnet_node WHERE node IS NOT NULL",
                rs -> new LoggedNode(rs.getInt(1), rs.getInt(2), SourceDirectory.kindOf(rs.getString(3)),
                        new NodeRef(rs.getString(4), rs.getString(5))));
    }

    /**
     * A stored value's text read back as its type. A row this logger did not write may hold text that is not of
     * its type: it is kept as a string (shown, not plotted) and named in the log rather than failing the query.
     */
    private static TypedValue storedValue(ValueType type, String text, int sourceId) {
        try {
            return TypedValue.parse(type, text);
        } catch (IllegalArgumentException notOfItsType) {
            LOG.warn("datavalue_log: source {} has a {} value that is not one ({}); shown as text", sourceId, type,
                    notOfItsType.getMessage());
            return TypedValue.of(text);
        }
    }

    /** The first id of a fresh block of {@link Schema#SOURCE_BLOCK} global source ids. */
    public int reserveSourceBlock() throws SQLException {
        return query("SELECT nextval('fdnet_sourceid_block')", rs -> (int) rs.getLong(1)).get(0);
    }

    /** Every stored event of the nodes with {@code from <= time <= to}, in time order. */
    public List<NetworkEvent> history(int[] sourceIds, long from, long to) throws SQLException {
        Connection c = pool.borrow();
        boolean broken = true;
        try {
            List<NetworkEvent> out = new ArrayList<>();
            Array ids = c.createArrayOf("integer", box(sourceIds));
            try (PreparedStatement ps = c.prepareStatement("SELECT sourceid, time, value, typevalue FROM datavalue_log"
                    + " WHERE sourceid = ANY (?) AND time BETWEEN ? AND ?")) {
                bind(ps, ids, from, to);
                try (ResultSet rs = ps.executeQuery()) {
                    while (rs.next()) {
                        out.add(new DataValueEvent(rs.getInt(1), rs.getLong(2),
                                storedValue(ValueType.fromCode(rs.getInt(4)), rs.getString(3), rs.getInt(1))));
                    }
                }
            }
            try (PreparedStatement ps = c.prepareStatement("SELECT sourceid, time, value FROM procvalue_log"
                    + " WHERE sourceid = ANY (?) AND time BETWEEN ? AND ?")) {
                bind(ps, ids, from, to);
                try (ResultSet rs = ps.executeQuery()) {
                    while (rs.next()) {
                        out.add(new RelationValueEvent(rs.getInt(1), rs.getLong(2), rs.getString(3)));
                    }
                }
            }
            try (PreparedStatement ps = c.prepareStatement("SELECT sourceid, time, sourcetype, command, params_id,"
                    + " params_type FROM netcommand_log WHERE sourceid = ANY (?) AND time BETWEEN ? AND ?")) {
                bind(ps, ids, from, to);
                try (ResultSet rs = ps.executeQuery()) {
                    while (rs.next()) {
                        out.add(new NetworkCommandEvent(rs.getInt(1), rs.getLong(2), rs.getString(3),
                                NetworkCommand.valueOf(rs.getString(4).toUpperCase(Locale.ROOT)), rs.getString(5),
                                rs.getString(6)));
                    }
                }
            }
            out.sort(Comparator.comparingLong(NetworkEvent::time).thenComparingInt(NetworkEvent::sourceId));
            broken = false;
            return out;
        } finally {
            pool.giveBack(c, broken);
        }
    }

    private static void bind(PreparedStatement ps, Array ids, long from, long to) throws SQLException {
        ps.setArray(1, ids);
        ps.setLong(2, from);
        ps.setLong(3, to);
    }

    private static Integer[] box(int[] ids) {
        Integer[] boxed = new Integer[ids.length];
        for (int i = 0; i < ids.length; i++) {
            boxed[i] = ids[i];
        }
        return boxed;
    }

    private interface RowMapper<T> {
        T map(ResultSet rs) throws SQLException;
    }

    private <T> List<T> query(String sql, RowMapper<T> mapper) throws SQLException {
        Connection c = pool.borrow();
        boolean broken = true;
        try (Statement s = c.createStatement(); ResultSet rs = s.executeQuery(sql)) {
            List<T> out = new ArrayList<>();
            while (rs.next()) {
                out.add(mapper.map(rs));
            }
            broken = false;
            return out;
        } finally {
            pool.giveBack(c, broken);
        }
    }

    @Override
    public void close() {
        pool.close();
    }
}

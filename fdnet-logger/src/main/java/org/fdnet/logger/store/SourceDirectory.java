package org.fdnet.logger.store;

import java.sql.SQLException;
import java.util.ArrayList;
import java.util.BitSet;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.UUID;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.event.wire.LoggedRun;
import org.fdnet.event.wire.RunFrame;
import org.fdnet.logger.cache.RunProgress;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * Runs and nodes as the logger knows them: which run a UUID is, which global source id a (run, core-local
 * id) is, and what each node is called. New mappings are handed out from a reserved block of ids without
 * touching the database, and kept as "unsaved" until the writer commits them together with (or before)
 * the first event that uses them.
 *
 * <pre>
 *   receiver: HELLO(run uuid) ─openRun─▶ RunProgress      EVENTS ─globalId(run, local)─▶ sourceid
 *   writer:   unsavedMappings() ─INSERT fdnet_node─▶ saved(...)
 *   viewer:   nodes(filter), seenFromStart(sourceid)
 * </pre>
 */
public final class SourceDirectory {
    private final EventStore store;
    private final Map<UUID, RunProgress> runs = new HashMap<>();
    private final Map<Integer, Map<Integer, Integer>> globalIds = new HashMap<>();
    private final Map<Integer, LoggedNode> names = new HashMap<>();
    private final BitSet seenFromStart = new BitSet();
    private final List<NodeMapping> unsaved = new ArrayList<>();
    private int nextId;
    private int blockEnd;

    public SourceDirectory(EventStore store) {
        this.store = store;
    }

    /** Loads the names of every node already in the database. */
    public synchronized void load() throws SQLException {
        for (LoggedNode n : store.loadNodes()) {
            names.put(n.sourceId(), n);
        }
    }

    /** The logger's id of the run a core names by {@code uuid} (what viewers list and replay), once it said HELLO. */
    public synchronized java.util.OptionalInt runIdOf(UUID uuid) {
        RunProgress run = runs.get(uuid);
        return run == null ? java.util.OptionalInt.empty() : java.util.OptionalInt.of(run.runId());
    }

    /** The run of a core's HELLO: known in memory, found in the database, or created there. */
    public RunProgress openRun(UUID uuid, String coreName) throws SQLException {
        synchronized (this) {
            RunProgress known = runs.get(uuid);
            if (known != null) {
                return known;
            }
        }
        EventStore.RunRow row = store.openRun(uuid, coreName);
        List<NodeMapping> mappings = store.loadMappings(row.runId());
        synchronized (this) {
            RunProgress known = runs.get(uuid);
            if (known != null) {
                return known;
            }
            RunProgress run = new RunProgress(row.runId(), uuid, row.committedSeq());
            Map<Integer, Integer> map = globalIds.computeIfAbsent(row.runId(), k -> new HashMap<>());
            for (NodeMapping m : mappings) {
                map.put(m.localId(), m.sourceId());
            }
            runs.put(uuid, run);
            return run;
        }
    }

    /** Every stream the database holds, with its network run (see {@link EventStore#loadRuns}). */
    public List<LoggedRun> runs() throws SQLException {
        return store.loadRuns();
    }

    /** Records that {@code run} is host {@code part.host()} of the network run {@code part.run()}. */
    public void joinNetworkRun(RunProgress run, RunFrame part) throws SQLException {
        store.joinNetworkRun(run.runId(), part);
    }

    /** The global id of a run's local node id; new ids come from a reserved block (the database when empty). */
    public synchronized int globalId(RunProgress run, int localId) throws SQLException {
        Map<Integer, Integer> map = globalIds.computeIfAbsent(run.runId(), k -> new HashMap<>());
        Integer id = map.get(localId);
        if (id != null) {
            return id;
        }
        if (nextId >= blockEnd) {
            nextId = store.reserveSourceBlock();
            blockEnd = nextId + Schema.SOURCE_BLOCK;
        }
        int global = nextId++;
        map.put(localId, global);
        seenFromStart.set(global);
        unsaved.add(new NodeMapping(global, run.runId(), localId));
        return global;
    }

    /** A node's name arrived (the event carries the global id already). */
    public synchronized void named(RunProgress run, NodeNamedEvent e) {
        names.put(e.sourceId(), new LoggedNode(e.sourceId(), run.runId(), e.kind(), e.name()));
    }

    public synchronized List<NodeMapping> unsavedMappings() {
        return new ArrayList<>(unsaved);
    }

    public synchronized void saved(List<NodeMapping> mappings) {
        unsaved.removeAll(mappings);
    }

    /** True when this logger received the node's very first event: its cache then holds all it did not write. */
    public synchronized boolean seenFromStart(int sourceId) {
        return seenFromStart.get(sourceId);
    }

    /** Nodes matching {@code ""} (all), {@code Node} (any module) or {@code Module/Node}; newest run first. */
    public synchronized List<LoggedNode> nodes(String filter) {
        List<LoggedNode> out = new ArrayList<>();
        for (LoggedNode n : names.values()) {
            if (matches(n.name(), filter)) {
                out.add(n);
            }
        }
        out.sort((a, b) -> a.runId() != b.runId() ? Integer.compare(b.runId(), a.runId())
                : Integer.compare(a.sourceId(), b.sourceId()));
        return out;
    }

    /** Whether {@code ref} is named by {@code filter}: {@code ""} (every node), {@code Node} (any module) or {@code Module/Node}. */
    public static boolean matches(NodeRef ref, String filter) {
        if (filter.isEmpty()) {
            return true;
        }
        int slash = filter.indexOf('/');
        return slash < 0 ? ref.node().equals(filter) : ref.toString().equals(filter);
    }

    public static NodeKind kindOf(String text) {
        return "data".equals(text) ? NodeKind.DATA : NodeKind.RELATION;
    }
}

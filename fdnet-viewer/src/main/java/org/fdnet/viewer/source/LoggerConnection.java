package org.fdnet.viewer.source;

import java.io.IOException;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.HashMap;
import java.util.concurrent.ConcurrentHashMap;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.wire.LoggedRun;
import java.util.List;
import java.util.Map;
import java.util.function.Consumer;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.client.ViewerClient;
import org.fdnet.event.wire.HistoryColumns;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.viewer.data.NodeSelection;
import org.fdnet.viewer.data.PlotData;

/**
 * The viewer's link to the logger's sender server (the core's {@link ViewerClient}): lists the logger's
 * nodes and runs, resolves names to source ids, streams the monitored nodes live into a {@link PlotData},
 * and loads history (cache and database, merged by the logger) into it.
 *
 * <pre>
 *   watch(selection) ─LIST_NODES─▶ newest run's source ids ─MONITOR─▶ logger
 *   logger ─MONITOR_EVENTS─▶ live listener ─▶ PlotData (while not paused by the caller's choice)
 *   loadHistory(from, to) ─HISTORY─▶ HistoryColumns (times, numbers) in time order ─▶ PlotData
 * </pre>
 */
public final class LoggerConnection implements AutoCloseable {
    private final String address;
    private final ViewerClient client;
    private final PlotData live;
    private final Map<Integer, Long> offsetOfStream = new ConcurrentHashMap<>();
    private final Map<Integer, Long> offsetOfSource = new ConcurrentHashMap<>();

    /** Connects to {@code host:port}; live events of watched nodes go to {@code live}. */
    public LoggerConnection(String address, PlotData live) throws IOException {
        this(address, live, e -> { });
    }

    /** As above; {@code tap} sees every monitored event too (after {@code live} took it). */
    public LoggerConnection(String address, PlotData live, Consumer<NetworkEvent> tap) throws IOException {
        this.address = address;
        this.live = live;
        int colon = address.lastIndexOf(':');
        if (colon <= 0 || colon == address.length() - 1) {
            throw new IllegalArgumentException("logger address '" + address + "': expected HOST:PORT, e.g. 127.0.0.1:5556");
        }
        int port;
        try {
            port = Integer.parseInt(address.substring(colon + 1));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("logger address '" + address + "': the port is not a number");
        }
        try {
            client = new ViewerClient(address.substring(0, colon), port, "fdnet viewer", e -> {
                NetworkEvent onAxis = shift(e);
                live.accept(onAxis);
                tap.accept(onAxis);
            });
        } catch (IOException e) {
            throw new IOException("cannot reach the logger's viewer service at " + address + ": " + e.getMessage(), e);
        }
    }

    public String address() {
        return address;
    }

    /** The logger's Data nodes, newest run first. */
    public List<LoggedNode> dataNodes() throws IOException {
        List<LoggedNode> out = new ArrayList<>();
        for (LoggedNode n : client.nodes("")) {
            if (n.kind() == NodeKind.DATA) {
                out.add(n);
            }
        }
        return out;
    }

    /**
     * The runs the logger knows (its database and cache), newest first, each with every host's Data nodes: the
     * streams of one network run are one run. Learns each stream's clock offset on the way (see {@link #shift}).
     */
    public List<RunInfo> runs() throws IOException {
        Map<Integer, LoggedRun> streams = new HashMap<>();
        for (LoggedRun r : client.runs()) {
            streams.put(r.streamId(), r);
            offsetOfStream.put(r.streamId(), r.clockOffsetMicros());
        }
        Map<String, List<LoggedNode>> byRun = new LinkedHashMap<>();
        for (LoggedNode n : dataNodes()) {
            LoggedRun s = streams.get(n.runId());
            String key = s == null || s.networkRunId() == 0 ? "stream " + n.runId() : "run " + s.networkRunId();
            byRun.computeIfAbsent(key, k -> new ArrayList<>()).add(n);
            offsetOfSource.put(n.sourceId(), offsetOfStream.getOrDefault(n.runId(), 0L));
        }
        List<RunInfo> runs = new ArrayList<>();
        byRun.forEach((key, nodes) -> {
            int first = nodes.stream().mapToInt(LoggedNode::runId).min().orElseThrow();
            LoggedRun s = streams.get(first);
            Map<Integer, String> hosts = new HashMap<>();
            nodes.forEach(n -> {
                LoggedRun of = streams.get(n.runId());
                if (of != null) {
                    hosts.put(n.runId(), of.host());
                }
            });
            runs.add(s == null ? RunInfo.ofStream(first, nodes)
                    : new RunInfo(first, s.network(), s.hostCount(), s.startedMicros(), nodes, hosts));
        });
        runs.sort((a, b) -> Integer.compare(b.runId(), a.runId()));
        return runs;
    }

    /**
     * The event on the run's coordinator's time axis: its time less its host's clock offset (as the coordinator
     * measured it at deployment, see docs/viewer.md). Only Data values are plotted; other events pass unchanged.
     */
    public NetworkEvent shift(NetworkEvent e) {
        long offset = offsetOfSource.getOrDefault(e.sourceId(), 0L);
        if (offset == 0 || !(e instanceof DataValueEvent v)) {
            return e;
        }
        return new DataValueEvent(v.sourceId(), v.time() - offset, v.value());
    }

    /**
     * The newest run's node of that name ({@code Module/Node} exactly, or {@code Node} in any module).
     *
     * @throws IllegalArgumentException naming the node when the logger does not know it
     */
    public LoggedNode resolve(NodeSelection selection) throws IOException {
        for (LoggedNode n : client.nodes(selection.name())) {
            if (n.kind() == NodeKind.DATA) {
                return n;
            }
        }
        throw new IllegalArgumentException("node '" + selection.name() + "': the logger at " + address
                + " knows no Data of that name (fdnet viewer shows them in its tree of the run's Datas)");
    }

    /** Tracks the nodes in the live data and starts monitoring them; answers the resolved nodes. */
    public List<LoggedNode> watch(List<NodeSelection> selections) throws IOException {
        if (offsetOfStream.isEmpty()) {
            runs(); // learn the hosts' clock offsets before the first live value
        }
        List<LoggedNode> nodes = new ArrayList<>();
        for (NodeSelection s : selections) {
            LoggedNode n = resolve(s);
            live.track(n.sourceId(), label(n), s.unit());
            nodes.add(n);
        }
        watchNodes(nodes);
        return nodes;
    }

    /** Monitors nodes already tracked in the live data. */
    public void watchNodes(List<LoggedNode> nodes) throws IOException {
        for (LoggedNode n : nodes) {
            live.track(n.sourceId(), label(n), "");
        }
        client.monitor(nodes.stream().mapToInt(LoggedNode::sourceId).toArray());
    }

    /** Every value of the sources with {@code from <= time <= to} (µs), in time order, into {@code into}. */
    public int loadHistory(int[] sourceIds, long from, long to, PlotData into) throws IOException {
        HistoryColumns events = client.historyColumns(sourceIds, from, to); // numbers without an object each
        events.shiftTimes(source -> offsetOfSource.getOrDefault(source, 0L));
        into.accept(events);
        return events.size();
    }

    /**
     * The first and last time (µs, on the run's time axis) of the sources' recorded values, or null when they have
     * none: how long a run lasted, measured on a few of its Datas.
     */
    public long[] span(int[] sourceIds) throws IOException {
        HistoryColumns events = client.historyColumns(sourceIds, 0, Long.MAX_VALUE);
        events.shiftTimes(source -> offsetOfSource.getOrDefault(source, 0L));
        long first = Long.MAX_VALUE;
        long last = Long.MIN_VALUE;
        for (int i = 0; i < events.size(); i++) {
            first = Math.min(first, events.time(i));
            last = Math.max(last, events.time(i));
        }
        return events.size() == 0 ? null : new long[] {first, last};
    }

    /** The raw history of the sources (time order), for replay. */
    public List<NetworkEvent> history(int[] sourceIds, long from, long to) throws IOException {
        List<NetworkEvent> events = new ArrayList<>(client.history(sourceIds, from, to));
        events.replaceAll(this::shift);
        events.sort(java.util.Comparator.comparingLong(NetworkEvent::time)); // hosts' offsets may reorder a little
        return events;
    }

    /** µs the clock of the host that recorded {@code sourceId} is ahead of its run's coordinator (0 when not known). */
    public long clockOffsetOf(int sourceId) {
        return offsetOfSource.getOrDefault(sourceId, 0L);
    }

    /** How a node is named in legends: {@code Module/Node}. */
    public static String label(LoggedNode n) {
        return n.name().module().isEmpty() ? n.name().node() : n.name().module() + "/" + n.name().node();
    }

    @Override
    public void close() {
        client.close();
    }
}

package org.fdnet.event.wire;

/**
 * A viewer's request to the logger's sender server, read and checked whole before the logger acts on it:
 * {@code LIST_NODES} (id, name filter), {@code LIST_RUNS} (id), {@code HISTORY} (id, node ids, from, to),
 * {@code MONITOR} / {@code UNMONITOR} (node ids). The viewer's client writes it with {@link #write}.
 *
 * @param type   the request's frame type
 * @param id     the request id the answer carries; 0 for MONITOR and UNMONITOR
 * @param filter a LIST_NODES name filter ({@code ""}, {@code Node} or {@code Module/Node}); empty otherwise
 * @param nodes  the logger's node ids for HISTORY, MONITOR and UNMONITOR (none in UNMONITOR: all); not copied
 * @param from   a HISTORY's first time, µs since the epoch, inclusive
 * @param to     a HISTORY's last time, µs since the epoch, inclusive
 */
public record ViewerRequest(MessageType type, int id, String filter, int[] nodes, long from, long to) {
    /** Most node ids one request may name. */
    public static final int MAX_NODES = 10_000;
    private static final int[] NO_NODES = {};

    /**
     * A LIST_NODES request.
     *
     * @param id     the request id
     * @param filter {@code ""} for every node, {@code Node} or {@code Module/Node}
     * @return a LIST_NODES request, without nodes or time range
     */
    public static ViewerRequest listNodes(int id, String filter) {
        return new ViewerRequest(MessageType.LIST_NODES, id, filter, NO_NODES, 0, 0);
    }

    /**
     * A LIST_RUNS request.
     *
     * @param id the request id
     * @return a LIST_RUNS request, with an empty filter and no nodes
     */
    public static ViewerRequest listRuns(int id) {
        return new ViewerRequest(MessageType.LIST_RUNS, id, "", NO_NODES, 0, 0);
    }

    /**
     * {@code type} is {@link MessageType#HISTORY}.
     *
     * @param type  {@link MessageType#HISTORY}
     * @param id    the request id
     * @param nodes the logger's node ids, at most {@link #MAX_NODES}
     * @param from  the first time, µs since the epoch, inclusive
     * @param to    the last time, µs since the epoch, inclusive
     * @return a request of {@code type}, with an empty filter; {@code nodes} is not copied
     */
    public static ViewerRequest history(MessageType type, int id, int[] nodes, long from, long to) {
        return new ViewerRequest(type, id, "", nodes, from, to);
    }

    /**
     * {@code type} is {@link MessageType#MONITOR} or {@link MessageType#UNMONITOR}.
     *
     * @param type  MONITOR or UNMONITOR
     * @param nodes the logger's node ids, at most {@link #MAX_NODES}; none in UNMONITOR stops all
     * @return a request of {@code type} with id 0, no filter and no time range
     */
    public static ViewerRequest monitor(MessageType type, int[] nodes) {
        return new ViewerRequest(type, 0, "", nodes, 0, 0);
    }

    /**
     * Appends this request's frame to {@code w}.
     *
     * @param w the writer to add the frame to
     */
    public void write(FrameWriter w) {
        w.begin(type);
        switch (type) {
            case LIST_NODES -> w.putInt(id).putString(filter);
            case LIST_RUNS -> w.putInt(id);
            case HISTORY -> putNodes(w.putInt(id)).putLong(from).putLong(to);
            default -> putNodes(w);
        }
    }

    private FrameWriter putNodes(FrameWriter w) {
        w.putInt(nodes.length);
        for (int n : nodes) {
            w.putInt(n);
        }
        return w;
    }

    /**
     * The request in {@code f}, or a {@link ProtocolException} naming what a viewer may not send.
     *
     * @param f a frame a viewer sent after the handshake
     * @return the request, checked whole
     * @throws ProtocolException when the type is not a viewer's request, the payload is malformed, it names more
     *                           than {@link #MAX_NODES} nodes or a negative id, or bytes trail a request
     *                           other than LIST_NODES
     */
    public static ViewerRequest read(Frame f) throws ProtocolException {
        switch (f.type()) {
            case LIST_NODES -> {
                return listNodes(f.getInt(), f.getString());
            }
            case LIST_RUNS -> {
                int id = f.getInt();
                f.expectEnd();
                return listRuns(id);
            }
            case HISTORY -> {
                int id = f.getInt();
                int[] nodes = nodeIds(f);
                long from = f.getLong();
                long to = f.getLong();
                f.expectEnd();
                return history(f.type(), id, nodes, from, to);
            }
            case MONITOR, UNMONITOR -> {
                int[] nodes = nodeIds(f);
                f.expectEnd();
                return monitor(f.type(), nodes);
            }
            default -> throw new ProtocolException("a viewer may not send " + f.type());
        }
    }

    private static int[] nodeIds(Frame f) throws ProtocolException {
        int n = f.getCount(4);
        if (n > MAX_NODES) {
            throw new ProtocolException("request names " + n + " nodes; at most " + MAX_NODES);
        }
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            ids[i] = f.getInt();
            if (ids[i] < 0) {
                throw new ProtocolException("negative node id " + ids[i]);
            }
        }
        return ids;
    }
}

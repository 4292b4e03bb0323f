package org.fdnet.event.wire;

import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkCommand;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * One event on the wire: {@code u8 kind, i32 sourceId, i64 time}, then per kind
 * <ul>
 *   <li>1 data: a typed value in binary ({@link ValueCodec}: {@code u8 valueType}, then e.g. {@code f64})</li>
 *   <li>2 relation: {@code string value}</li>
 *   <li>3 command: {@code string sourceType, u8 command (NetworkCommand ordinal), string paramsId, string paramsType}</li>
 *   <li>4 named: {@code u8 nodeKind (1 data, 2 relation), string module, string node}</li>
 * </ul>
 * Protocol version 1 sent a Data's value as text (and numbers as kinds 5 and 6 in plot answers only); version 2
 * sends every value in binary, so no side formats or parses a number.
 */
public final class EventCodec {
    static final int DATA = 1;
    static final int RELATION = 2;
    static final int COMMAND = 3;
    static final int NAMED = 4;
    /** The smallest encoded event: kind, source, time and a boolean value. */
    public static final int MIN_EVENT_BYTES = 1 + 4 + 8 + ValueCodec.MIN_VALUE_BYTES;

    private static final NetworkCommand[] COMMANDS = NetworkCommand.values();

    /**
     * How a reader turns the source id on the wire into the one it keeps: the logger maps a core's node ids to
     * global ids while decoding, so each event is built once. May wait (a new block of ids from the database).
     */
    @FunctionalInterface
    public interface SourceIdMap {
        /**
         * The id to keep for an id read from the wire.
         *
         * @param sourceIdOnWire the event's source id as the sender numbered it
         * @return the reader's id for the same node
         * @throws InterruptedException when the thread is interrupted while waiting for ids
         */
        int map(int sourceIdOnWire) throws InterruptedException;
    }

    private EventCodec() {
    }

    /**
     * Appends one event to the frame {@code w} is building.
     *
     * @param w     a writer inside an EVENTS, HISTORY_CHUNK or MONITOR_EVENTS frame
     * @param event the event, of any of the four kinds
     */
    public static void write(FrameWriter w, NetworkEvent event) {
        if (event instanceof DataValueEvent d) {
            head(w, DATA, d);
            ValueCodec.write(w, d.value());
        } else if (event instanceof RelationValueEvent r) {
            head(w, RELATION, r);
            w.putString(r.value());
        } else if (event instanceof NetworkCommandEvent c) {
            head(w, COMMAND, c);
            w.putString(c.sourceType()).putByte(c.command().ordinal())
                    .putString(c.paramsId()).putString(c.paramsType());
        } else {
            NodeNamedEvent n = (NodeNamedEvent) event;
            head(w, NAMED, n);
            w.putByte(n.kind() == NodeKind.DATA ? 1 : 2)
                    .putString(n.name().module()).putString(n.name().node());
        }
    }

    /**
     * The same event with another source id: the logger maps a core's ids to global ones.
     *
     * @param event    the event as received
     * @param sourceId the id to give it
     * @return a new event of the same kind, time and content
     */
    public static NetworkEvent withSource(NetworkEvent event, int sourceId) {
        if (event instanceof DataValueEvent d) {
            return d.withSource(sourceId);
        } else if (event instanceof RelationValueEvent r) {
            return new RelationValueEvent(sourceId, r.time(), r.value());
        } else if (event instanceof NetworkCommandEvent c) {
            return new NetworkCommandEvent(sourceId, c.time(), c.sourceType(), c.command(), c.paramsId(), c.paramsType());
        }
        NodeNamedEvent n = (NodeNamedEvent) event;
        return new NodeNamedEvent(sourceId, n.time(), n.kind(), n.name());
    }

    private static void head(FrameWriter w, int kind, NetworkEvent e) {
        w.putEventHead(kind, e.sourceId(), e.time());
    }

    /**
     * Reads one event at the frame's cursor.
     *
     * @param f a frame positioned on an event
     * @return the event, with the source id as sent
     * @throws ProtocolException when the kind, value type, command or node kind is unknown, or the payload ends
     *                           inside the event
     */
    public static NetworkEvent read(Frame f) throws ProtocolException {
        int kind = f.getByte();
        int source = f.getInt();
        long time = f.getLong();
        return body(f, kind, source, time);
    }

    /**
     * One event, built with {@code sources.map(id on the wire)} as its source id: what {@link #read(Frame)} then
     * {@link #withSource} give, with one object instead of two. The frame should have passed {@link #skip} first
     * when nothing may be mapped for a malformed frame.
     *
     * @param f       a frame positioned on an event
     * @param sources maps the source id on the wire to the one the event gets
     * @return the event, with the mapped source id
     * @throws ProtocolException    as {@link #read(Frame)}
     * @throws InterruptedException when {@code sources} is interrupted while waiting
     */
    public static NetworkEvent read(Frame f, SourceIdMap sources) throws ProtocolException, InterruptedException {
        int kind = f.getByte();
        int source = sources.map(f.getInt());
        long time = f.getLong();
        return body(f, kind, source, time);
    }

    /**
     * Steps over one event, checking it exactly as {@link #read(Frame)} does (kind, value type, command, node
     * kind, every length) without building it: a receiver checks a whole frame before it takes any event.
     *
     * @param f a frame positioned on an event; left on the next one
     * @throws ProtocolException when the event is malformed, as {@link #read(Frame)} would say
     */
    public static void skip(Frame f) throws ProtocolException {
        int kind = f.getByte();
        f.getInt();
        f.getLong();
        switch (kind) {
            case DATA -> ValueCodec.skip(f);
            case RELATION -> f.skipString();
            case COMMAND -> {
                f.skipString();
                command(f.getByte());
                f.skipString();
                f.skipString();
            }
            case NAMED -> {
                int nodeKind = f.getByte();
                if (nodeKind != 1 && nodeKind != 2) {
                    throw new ProtocolException("malformed " + f.type() + " frame: unknown node kind " + nodeKind);
                }
                f.skipString();
                f.skipString();
            }
            default -> throw new ProtocolException("malformed " + f.type() + " frame: unknown event kind " + kind);
        }
    }

    private static NetworkEvent body(Frame f, int kind, int source, long time) throws ProtocolException {
        try {
            return switch (kind) {
                case DATA -> new DataValueEvent(source, time, ValueCodec.read(f));
                case RELATION -> new RelationValueEvent(source, time, f.getString());
                case COMMAND -> new NetworkCommandEvent(source, time, f.getString(), command(f.getByte()),
                        f.getString(), f.getString());
                case NAMED -> named(f, source, time);
                default -> throw new ProtocolException("malformed " + f.type() + " frame: unknown event kind " + kind);
            };
        } catch (IllegalArgumentException e) {
            throw new ProtocolException("malformed " + f.type() + " frame: " + e.getMessage());
        }
    }

    private static NodeNamedEvent named(Frame f, int source, long time) throws ProtocolException {
        int kind = f.getByte();
        if (kind != 1 && kind != 2) {
            throw new ProtocolException("malformed " + f.type() + " frame: unknown node kind " + kind);
        }
        String module = f.getString();
        String node = f.getString();
        return new NodeNamedEvent(source, time, kind == 1 ? NodeKind.DATA : NodeKind.RELATION, new NodeRef(module, node));
    }

    private static NetworkCommand command(int ordinal) throws ProtocolException {
        if (ordinal >= COMMANDS.length) {
            throw new ProtocolException("unknown network command " + ordinal);
        }
        return COMMANDS[ordinal];
    }
}

package org.fdnet.event.wire;

import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkCommand;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.event.ValueType;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * One event on the wire: {@code u8 kind, i32 sourceId, i64 time}, then per kind
 * <ul>
 *   <li>1 data: {@code u8 valueType, string value}</li>
 *   <li>2 relation: {@code string value}</li>
 *   <li>3 command: {@code string sourceType, u8 command (NetworkCommand ordinal), string paramsId, string paramsType}</li>
 *   <li>4 named: {@code u8 nodeKind (1 data, 2 relation), string module, string node}</li>
 * </ul>
 * and, only in answers to {@link MessageType#HISTORY_NUMBERS} ({@link #writeNumeric}), a Data's value whose text is
 * exactly what Java prints for its number:
 * <ul>
 *   <li>5 double value: {@code f64 value} (type DOUBLE, text {@code Double.toString(value)})</li>
 *   <li>6 long value: {@code i64 value}, |value| ≤ 2^53 (type LONG, text {@code Long.toString(value)})</li>
 * </ul>
 */
public final class EventCodec {
    static final int DATA = 1;
    static final int RELATION = 2;
    static final int COMMAND = 3;
    static final int NAMED = 4;
    static final int DOUBLE_VALUE = 5;
    static final int LONG_VALUE = 6;
    /** Longs up to this magnitude go as numbers: a viewer holds them as doubles, exactly. */
    private static final long EXACT_IN_DOUBLE = 1L << 53;
    /** The smallest encoded event: kind, source, time and one empty string. */
    public static final int MIN_EVENT_BYTES = 1 + 4 + 8 + 4;

    private static final NetworkCommand[] COMMANDS = NetworkCommand.values();
    /** {@link ValueType} by code, looked up without {@code values()}'s copy per event (the intake's hot path). */
    private static final ValueType[] VALUE_TYPES = valueTypesByCode();

    /**
     * How a reader turns the source id on the wire into the one it keeps: the logger maps a core's node ids to
     * global ids while decoding, so each event is built once. May wait (a new block of ids from the database).
     */
    @FunctionalInterface
    public interface SourceIdMap {
        int map(int sourceIdOnWire) throws InterruptedException;
    }

    private EventCodec() {
    }

    public static void write(FrameWriter w, NetworkEvent event) {
        if (event instanceof DataValueEvent d) {
            head(w, DATA, d);
            w.putByte(d.type().code()).putString(d.value());
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
     * As {@link #write}, except that a Data's {@code DOUBLE} or {@code LONG} value whose text is what Java prints
     * for its number goes as that number (8 bytes, nothing to parse, the text made again exactly on demand).
     * For answers to {@link MessageType#HISTORY_NUMBERS} only: the logger encodes an event this way once and
     * keeps the bytes.
     */
    public static void writeNumeric(FrameWriter w, NetworkEvent event) {
        if (event instanceof DataValueEvent d && d.type() == ValueType.DOUBLE) {
            double v = canonicalDouble(d.value());
            if (v == v || "NaN".equals(d.value())) {
                w.putEventHead(DOUBLE_VALUE, d.sourceId(), d.time()).putLong(Double.doubleToRawLongBits(v));
                return;
            }
        } else if (event instanceof DataValueEvent d && d.type() == ValueType.LONG) {
            String text = d.value();
            if (looksLikeLong(text)) {
                try {
                    long v = Long.parseLong(text);
                    if (Long.toString(v).equals(text) && v >= -EXACT_IN_DOUBLE && v <= EXACT_IN_DOUBLE) {
                        w.putEventHead(LONG_VALUE, d.sourceId(), d.time()).putLong(v);
                        return;
                    }
                } catch (NumberFormatException notALong) {
                    // sent as text, as written
                }
            }
        }
        write(w, event);
    }

    /** The number whose {@code Double.toString} is exactly {@code text}; NaN when there is none (or it is NaN). */
    private static double canonicalDouble(String text) {
        if (text.isEmpty() || text.length() > 32) {
            return Double.NaN;
        }
        char c = text.charAt(0);
        if (c != '-' && (c < '0' || c > '9') && c != 'N' && c != 'I') {
            return Double.NaN;
        }
        try {
            double v = Double.parseDouble(text);
            return Double.toString(v).equals(text) ? v : Double.NaN;
        } catch (NumberFormatException notADouble) {
            return Double.NaN;
        }
    }

    private static boolean looksLikeLong(String text) {
        int n = text.length();
        if (n == 0 || n > 20) {
            return false;
        }
        for (int i = 0; i < n; i++) {
            char c = text.charAt(i);
            if ((c < '0' || c > '9') && !(i == 0 && c == '-')) {
                return false;
            }
        }
        return true;
    }

    /** The same event with another source id: the logger maps a core's ids to global ones. */
    public static NetworkEvent withSource(NetworkEvent event, int sourceId) {
        if (event instanceof DataValueEvent d) {
            return new DataValueEvent(sourceId, d.time(), d.type(), d.value());
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
     */
    public static void skip(Frame f) throws ProtocolException {
        int kind = f.getByte();
        f.getInt();
        f.getLong();
        switch (kind) {
            case DATA -> {
                valueType(f.getByte());
                f.skipString();
            }
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
                case DATA -> new DataValueEvent(source, time, valueType(f.getByte()), f.getString());
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

    private static ValueType valueType(int code) throws ProtocolException {
        ValueType t = code < VALUE_TYPES.length ? VALUE_TYPES[code] : null;
        if (t == null) {
            throw new ProtocolException("unknown value type code " + code);
        }
        return t;
    }

    private static ValueType[] valueTypesByCode() {
        int max = 0;
        for (ValueType t : ValueType.values()) {
            max = Math.max(max, t.code());
        }
        ValueType[] byCode = new ValueType[max + 1];
        for (ValueType t : ValueType.values()) {
            byCode[t.code()] = t;
        }
        return byCode;
    }

    private static NetworkCommand command(int ordinal) throws ProtocolException {
        if (ordinal >= COMMANDS.length) {
            throw new ProtocolException("unknown network command " + ordinal);
        }
        return COMMANDS[ordinal];
    }
}

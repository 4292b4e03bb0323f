package org.fdnet.event.wire;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.event.TypedValue;
import org.fdnet.event.ValueType;

/**
 * A history answer kept as columns, for a viewer that plots it: times, source ids, and each Data value of
 * type {@code LONG} or {@code DOUBLE} as its 8 bytes (the wire's binary value, {@link ValueCodec}). No object
 * is made per number; any other event (a vector, a string, a Relation's status, a command — rare in a plot's
 * range) is decoded as an event when it arrives. A number's text is made only when asked ({@link #text}), its
 * event only when asked ({@link #event}).
 *
 * <pre>
 *   HISTORY_CHUNK ──{@link #appendAll}──▶ times[] · sources[] · valueTypes[] · numbers (8 bytes each, read in place)
 *                                      └─ other events decoded ──▶ event(i) / text(i) on demand
 * </pre>
 *
 * Built by one thread (the client's reader), then handed over whole; not for concurrent building.
 */
public final class HistoryColumns {
    /** A Data's number event: head (13 bytes), value type (1), value (8). */
    private static final int NUMBER_EVENT_BYTES = 1 + 4 + 8 + ValueCodec.NUMBER_BYTES;
    private static final VarHandle LONG_AT = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle INT_AT = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.BIG_ENDIAN);
    private static final int DOUBLE = ValueType.DOUBLE.code();
    private static final int LONG = ValueType.LONG.code();
    private int size;
    private long[] times = new long[16];
    private int[] sources = new int[16];
    /** The value type code of a Data's number; 0 for an event kept in {@link #decoded}. */
    private byte[] numberTypes = new byte[16];
    /** A LONG as itself, a DOUBLE as its bits: exact either way. */
    private long[] numberBits = new long[16];
    private NetworkEvent[] decoded;

    /**
     * Makes room for {@code more} events (a chunk's count) at once.
     *
     * @param more how many events are about to be appended
     */
    public void reserve(int more) {
        int need = size + more;
        if (need > times.length) {
            int n = Math.max(need, times.length * 2);
            times = Arrays.copyOf(times, n);
            sources = Arrays.copyOf(sources, n);
            numberTypes = Arrays.copyOf(numberTypes, n);
            numberBits = Arrays.copyOf(numberBits, n);
            if (decoded != null) {
                decoded = Arrays.copyOf(decoded, n);
            }
        }
    }

    /**
     * Reads the frame's next {@code n} events into the columns: a Data's number (the usual content of a plot's
     * answer) straight from the frame's array, 22 bytes each; anything else through {@link #append}.
     *
     * @param f a frame positioned on its first event, e.g. a checked HISTORY_CHUNK
     * @param n how many events to read
     * @throws ProtocolException when an event is malformed
     */
    public void appendAll(Frame f, int n) throws ProtocolException {
        reserve(n);
        byte[] b = f.array();
        for (int i = 0; i < n; i++) {
            int at = f.arrayPosition();
            int type = f.remainingBytes() >= NUMBER_EVENT_BYTES && b[at] == EventCodec.DATA ? b[at + 13] : 0;
            if (type != DOUBLE && type != LONG) {
                append(f);
                continue;
            }
            sources[size] = (int) INT_AT.get(b, at + 1);
            times[size] = (long) LONG_AT.get(b, at + 5);
            numberTypes[size] = (byte) type;
            numberBits[size] = (long) LONG_AT.get(b, at + 14);
            size++;
            f.skip(NUMBER_EVENT_BYTES);
        }
    }

    /**
     * Reads the frame's next event (the {@link EventCodec} layout) into the columns.
     *
     * @param f a frame positioned on an event
     * @throws ProtocolException when the event is malformed
     */
    public void append(Frame f) throws ProtocolException {
        reserve(1);
        NetworkEvent e = EventCodec.read(f);
        times[size] = e.time();
        sources[size] = e.sourceId();
        if (e instanceof DataValueEvent d && d.value().isNumber()) {
            numberTypes[size] = (byte) d.type().code();
            numberBits[size] = d.type() == ValueType.LONG ? d.value().longValue()
                    : Double.doubleToRawLongBits(d.value().doubleValue());
        } else {
            if (decoded == null) {
                decoded = new NetworkEvent[times.length];
            }
            decoded[size] = e;
            numberTypes[size] = 0;
        }
        size++;
    }

    /**
     * How many events the columns hold.
     *
     * @return the count; valid indexes are 0 to this minus one
     */
    public int size() {
        return size;
    }

    /**
     * Moves each event's time back by its source's offset (a viewer putting every host on one time axis).
     *
     * @param offsetOfSource the clock offset of a source's host, µs ahead of the coordinator
     */
    public void shiftTimes(java.util.function.IntToLongFunction offsetOfSource) {
        for (int i = 0; i < size; i++) {
            times[i] -= offsetOfSource.applyAsLong(sources[i]);
        }
    }

    /**
     * Event {@code i}'s time.
     *
     * @param i the event's index
     * @return µs since the epoch (shifted, after {@link #shiftTimes})
     * @throws IndexOutOfBoundsException when {@code i} is outside 0 to {@link #size()} minus one
     */
    public long time(int i) {
        return times[check(i)];
    }

    /**
     * Event {@code i}'s source.
     *
     * @param i the event's index
     * @return the logger's id of the node
     * @throws IndexOutOfBoundsException when {@code i} is outside 0 to {@link #size()} minus one
     */
    public int sourceId(int i) {
        return sources[check(i)];
    }

    /**
     * Whether event {@code i} is a Data's value.
     *
     * @param i the event's index
     * @return true for a Data value of any type
     * @throws IndexOutOfBoundsException when {@code i} is out of range
     */
    public boolean isDataValue(int i) {
        return numberTypes[check(i)] != 0 || decoded[i] instanceof DataValueEvent;
    }

    /**
     * The value type of a Data's value; {@code null} for any other event.
     *
     * @param i the event's index
     * @return the type, or null
     * @throws IndexOutOfBoundsException when {@code i} is out of range
     */
    public ValueType valueType(int i) {
        if (numberTypes[check(i)] != 0) {
            return ValueType.fromCode(numberTypes[i]);
        }
        return decoded[i] instanceof DataValueEvent d ? d.type() : null;
    }

    /**
     * Whether {@link #number} holds the value: a Data's {@code LONG} or {@code DOUBLE} value.
     *
     * @param i the event's index
     * @return true when {@link #number} may be called
     * @throws IndexOutOfBoundsException when {@code i} is out of range
     */
    public boolean hasNumber(int i) {
        return numberTypes[check(i)] != 0;
    }

    /**
     * The value as a double (only when {@link #hasNumber}).
     *
     * @param i the event's index
     * @return the number, read in place
     * @throws IllegalStateException when event {@code i} has no number
     */
    public double number(int i) {
        if (!hasNumber(i)) {
            throw new IllegalStateException("event " + i + " has no numeric value");
        }
        return numberTypes[i] == DOUBLE ? Double.longBitsToDouble(numberBits[i]) : numberBits[i];
    }

    /**
     * A Data's or Relation's value as text (made now); {@code null} for commands and node names.
     *
     * @param i the event's index
     * @return the value's text form, or null
     * @throws IndexOutOfBoundsException when {@code i} is out of range
     */
    public String text(int i) {
        if (numberTypes[check(i)] != 0) {
            return typed(i).text();
        }
        NetworkEvent e = decoded[i];
        if (e instanceof DataValueEvent d) {
            return d.value().text();
        }
        return e instanceof RelationValueEvent r ? r.value() : null;
    }

    /**
     * Event {@code i} as an object (made now for numbers).
     *
     * @param i the event's index
     * @return the event: a number's made now, with the time {@link #time} gives; any other as decoded, with its time as
     *         the logger sent it (not shifted)
     * @throws IndexOutOfBoundsException when {@code i} is out of range
     */
    public NetworkEvent event(int i) {
        if (numberTypes[check(i)] != 0) {
            return new DataValueEvent(sources[i], times[i], typed(i));
        }
        return decoded[i];
    }

    private TypedValue typed(int i) {
        return numberTypes[i] == DOUBLE ? TypedValue.of(Double.longBitsToDouble(numberBits[i])) : TypedValue.of(numberBits[i]);
    }

    /**
     * Every event as an object, in order.
     *
     * @return a new list; each number's event is made now
     */
    public List<NetworkEvent> events() {
        List<NetworkEvent> out = new ArrayList<>(size);
        for (int i = 0; i < size; i++) {
            out.add(event(i));
        }
        return out;
    }

    private int check(int i) {
        if (i < 0 || i >= size) {
            throw new IndexOutOfBoundsException("event " + i + " of " + size);
        }
        return i;
    }
}

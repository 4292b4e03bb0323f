package org.fdnet.event.wire;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.event.ValueType;

/**
 * A history answer kept as columns, for a viewer that plots it: times, source ids, and each Data value of
 * type {@code LONG} or {@code DOUBLE} as a double — sent as a number by the logger (an answer to
 * {@link MessageType#HISTORY_NUMBERS}), or else read from its text straight from the frame's bytes. No object
 * and no String is made per event; a value's text is kept as bytes and becomes a String only when asked
 * ({@link #text}), an event only when asked ({@link #event}). Commands and node names (rare in a plot's
 * range) are decoded as events when they arrive.
 *
 * <pre>
 *   HISTORY_CHUNK ──{@link #append}──▶ times[] · sources[] · numbers[] (+ hasNumber) · text bytes + offsets
 *   (events as numbers: 8 bytes read; as text: parsed by AsciiNumber)
 *                                       └─▶ event(i) / text(i) on demand
 * </pre>
 *
 * Built by one thread (the client's reader), then handed over whole; not for concurrent building.
 */
public final class HistoryColumns {
    private static final int VALUE_TYPE_CODES = ValueType.values().length; // codes 1..n
    private static final int NUMBER_EVENT_BYTES = 1 + 4 + 8 + 8;
    private static final VarHandle LONG_AT = MethodHandles.byteArrayViewVarHandle(long[].class, ByteOrder.BIG_ENDIAN);
    private static final VarHandle INT_AT = MethodHandles.byteArrayViewVarHandle(int[].class, ByteOrder.BIG_ENDIAN);
    private static final int DOUBLE = ValueType.DOUBLE.code();
    private static final int LONG = ValueType.LONG.code();
    private int size;
    private long[] times = new long[16];
    private int[] sources = new int[16];
    private byte[] kinds = new byte[16];
    private byte[] valueTypes = new byte[16];
    private double[] numbers = new double[16];
    private boolean[] hasNumber = new boolean[16];
    private int[] textEnd = new int[16];
    private byte[] text = new byte[256];
    private int textLength;
    private NetworkEvent[] decoded;

    /** Makes room for {@code more} events (a chunk's count) at once. */
    public void reserve(int more) {
        int need = size + more;
        if (need > times.length) {
            int n = Math.max(need, times.length * 2);
            times = Arrays.copyOf(times, n);
            sources = Arrays.copyOf(sources, n);
            kinds = Arrays.copyOf(kinds, n);
            valueTypes = Arrays.copyOf(valueTypes, n);
            numbers = Arrays.copyOf(numbers, n);
            hasNumber = Arrays.copyOf(hasNumber, n);
            textEnd = Arrays.copyOf(textEnd, n);
            if (decoded != null) {
                decoded = Arrays.copyOf(decoded, n);
            }
        }
    }

    /**
     * Reads the frame's next {@code n} events into the columns: numbers (kinds 5 and 6, the usual content of a
     * plot's answer) straight from the frame's array, 21 bytes each; anything else through {@link #append}.
     */
    public void appendAll(Frame f, int n) throws ProtocolException {
        reserve(n);
        byte[] b = f.array();
        for (int i = 0; i < n; i++) {
            int at = f.arrayPosition();
            int kind = f.remainingBytes() >= NUMBER_EVENT_BYTES ? b[at] : 0;
            if (kind != EventCodec.DOUBLE_VALUE && kind != EventCodec.LONG_VALUE) {
                append(f);
                continue;
            }
            long bits = (long) LONG_AT.get(b, at + 13);
            boolean isDouble = kind == EventCodec.DOUBLE_VALUE;
            times[size] = (long) LONG_AT.get(b, at + 5);
            sources[size] = (int) INT_AT.get(b, at + 1);
            kinds[size] = (byte) kind;
            valueTypes[size] = (byte) (isDouble ? DOUBLE : LONG);
            numbers[size] = isDouble ? Double.longBitsToDouble(bits) : bits;
            hasNumber[size] = true;
            textEnd[size] = textLength;
            size++;
            f.skip(NUMBER_EVENT_BYTES);
        }
    }

    /** Reads the frame's next event (the {@link EventCodec} layout) into the columns. */
    public void append(Frame f) throws ProtocolException {
        reserve(1);
        int kind = f.peekByte();
        if (kind != EventCodec.DATA && kind != EventCodec.RELATION && kind != EventCodec.DOUBLE_VALUE
                && kind != EventCodec.LONG_VALUE) {
            NetworkEvent e = EventCodec.read(f);
            if (decoded == null) {
                decoded = new NetworkEvent[times.length];
            }
            decoded[size] = e;
            put(kind, e.sourceId(), e.time(), 0);
            textEnd[size] = textLength;
            size++;
            return;
        }
        f.getByte();
        int source = f.getInt();
        long time = f.getLong();
        if (kind == EventCodec.DOUBLE_VALUE || kind == EventCodec.LONG_VALUE) {
            long bits = f.getLong();
            put(kind, source, time, kind == EventCodec.DOUBLE_VALUE ? DOUBLE : LONG);
            numbers[size] = kind == EventCodec.DOUBLE_VALUE ? Double.longBitsToDouble(bits) : bits;
            hasNumber[size] = true;
            textEnd[size] = textLength;
            size++;
            return;
        }
        int type = kind == EventCodec.DATA ? f.getByte() : 0;
        if (kind == EventCodec.DATA && (type < 1 || type > VALUE_TYPE_CODES)) {
            throw new ProtocolException("unknown value type code " + type);
        }
        int start = f.skipString();
        int end = f.arrayPosition();
        byte[] b = f.array();
        put(kind, source, time, type);
        keepText(b, start, end);
        if (type == DOUBLE || type == LONG) {
            try {
                numbers[size] = type == DOUBLE ? AsciiNumber.parseDouble(b, start, end)
                        : AsciiNumber.parseLong(b, start, end);
                hasNumber[size] = true;
            } catch (NumberFormatException notANumber) {
                hasNumber[size] = false; // kept as text: the viewer counts it as not plotted
            }
        }
        size++;
    }

    private void put(int kind, int source, long time, int type) {
        times[size] = time;
        sources[size] = source;
        kinds[size] = (byte) kind;
        valueTypes[size] = (byte) type;
        hasNumber[size] = false;
        numbers[size] = 0;
    }

    private void keepText(byte[] b, int start, int end) {
        int n = end - start;
        if (textLength + n > text.length) {
            text = Arrays.copyOf(text, Math.max(text.length * 2, textLength + n));
        }
        System.arraycopy(b, start, text, textLength, n);
        textLength += n;
        textEnd[size] = textLength;
    }

    public int size() {
        return size;
    }

    /** Moves each event's time back by its source's offset (a viewer putting every host on one time axis). */
    public void shiftTimes(java.util.function.IntToLongFunction offsetOfSource) {
        for (int i = 0; i < size; i++) {
            times[i] -= offsetOfSource.applyAsLong(sources[i]);
        }
    }

    public long time(int i) {
        return times[check(i)];
    }

    public int sourceId(int i) {
        return sources[check(i)];
    }

    /** Whether event {@code i} is a Data's value. */
    public boolean isDataValue(int i) {
        int k = kinds[check(i)];
        return k == EventCodec.DATA || k == EventCodec.DOUBLE_VALUE || k == EventCodec.LONG_VALUE;
    }

    /** The value type of a Data's value; {@code null} for any other event. */
    public ValueType valueType(int i) {
        return isDataValue(i) ? ValueType.fromCode(valueTypes[i]) : null;
    }

    /** Whether {@link #number} holds the value: a Data's {@code LONG} or {@code DOUBLE} value that parses. */
    public boolean hasNumber(int i) {
        return hasNumber[check(i)];
    }

    /** The value as a double (only when {@link #hasNumber}). */
    public double number(int i) {
        if (!hasNumber(i)) {
            throw new IllegalStateException("event " + i + " has no numeric value");
        }
        return numbers[i];
    }

    /** A Data's or Relation's value as text (made now); {@code null} for commands and node names. */
    public String text(int i) {
        int k = kinds[check(i)];
        if (k == EventCodec.DOUBLE_VALUE) {
            return Double.toString(numbers[i]); // the logger sent it as a number only when this is its text
        } else if (k == EventCodec.LONG_VALUE) {
            return Long.toString((long) numbers[i]);
        } else if (k != EventCodec.DATA && k != EventCodec.RELATION) {
            return null;
        }
        int start = i == 0 ? 0 : textEnd[i - 1];
        return new String(text, start, textEnd[i] - start, StandardCharsets.UTF_8);
    }

    /** Event {@code i} as an object (made now for values). */
    public NetworkEvent event(int i) {
        int k = kinds[check(i)];
        if (k == EventCodec.DATA || k == EventCodec.DOUBLE_VALUE || k == EventCodec.LONG_VALUE) {
            return new DataValueEvent(sources[i], times[i], ValueType.fromCode(valueTypes[i]), text(i));
        } else if (k == EventCodec.RELATION) {
            return new RelationValueEvent(sources[i], times[i], text(i));
        }
        return decoded[i];
    }

    /** Every event as an object, in order. */
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

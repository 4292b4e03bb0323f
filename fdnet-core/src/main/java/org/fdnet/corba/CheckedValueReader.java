package org.fdnet.corba;

import java.util.function.Supplier;
import org.fdnet.corba.idl.NodeId;
import org.fdnet.corba.idl.SampledValue;
import org.fdnet.corba.idl.Value;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.corba.idl.ValueKind;
import org.omg.CORBA.MARSHAL;
import org.omg.CORBA.SystemException;
import org.omg.CORBA.portable.InputStream;

/**
 * Reads the values a peer sends — a link's {@link ValueBatch} ({@code deliver}) and a listener's
 * {@code SampledValues} ({@code valuesSampled}) — from a request's CDR bytes, in place of the helpers JacORB 3.9's IDL
 * compiler generates. Those allocate whatever a sequence's length claims when the length is the request's last
 * bytes (their check skips an empty rest), take a negative length to {@code new T[-n]}, and JacORB's stream reads
 * past the end of a truncated request; here every sequence length is checked against the bytes left before
 * anything is allocated, and a request that ends early is refused. The one refusal is a {@link MARSHAL} whose
 * message starts {@value #REFUSED}, which the caller gets as its call's failure; the servant goes on serving.
 */
public final class CheckedValueReader {
    /** How every refusal's message starts. */
    public static final String REFUSED = "FDNet refused the request's values: ";
    /** The fewest bytes one {@link Value} takes: its 4-byte kind and a 1-byte boolean. */
    private static final int MIN_VALUE_BYTES = 5;
    /** The fewest bytes one {@link SampledValue} takes: two empty strings (4-byte length, 1-byte NUL) and a value. */
    private static final int MIN_SAMPLED_BYTES = 2 * 5 + MIN_VALUE_BYTES;

    private CheckedValueReader() {
    }

    /** A link's batch, as {@code ValueSink.deliver} receives it. */
    public static ValueBatch batch(InputStream in) {
        return refusing("the batch", () -> {
            ValueBatch batch = new ValueBatch();
            batch.link = in.read_longlong();
            batch.firstSeq = in.read_longlong();
            batch.originStream = in.read_string();
            batch.originFirstSeq = in.read_longlong();
            batch.values = new Value[length(in, MIN_VALUE_BYTES, "the batch's values")];
            for (int i = 0; i < batch.values.length; i++) {
                batch.values[i] = value(in);
            }
            return batch;
        });
    }

    /** The latest values, as {@code RunningNetworkListener.valuesSampled} receives them. */
    public static SampledValue[] sampled(InputStream in) {
        return refusing("the sampled values", () -> {
            SampledValue[] sampled = new SampledValue[length(in, MIN_SAMPLED_BYTES, "the sampled values")];
            for (int i = 0; i < sampled.length; i++) {
                NodeId data = new NodeId(in.read_string(), in.read_string());
                sampled[i] = new SampledValue(data, value(in));
            }
            return sampled;
        });
    }

    /**
     * Runs a read, turning what JacORB's stream throws on bad bytes — a read past the end of a truncated request, its
     * own MARSHAL (a string's length) or BAD_PARAM (an enum value IDL does not know) — into this reader's refusal.
     */
    private static <T> T refusing(String what, Supplier<T> read) {
        try {
            return read.get();
        } catch (IndexOutOfBoundsException truncated) {
            throw refused(what + " end before their last field", truncated);
        } catch (SystemException bad) {
            if (bad.getMessage() != null && bad.getMessage().startsWith(REFUSED)) {
                throw bad;
            }
            throw refused(what + " cannot be read: " + bad, bad);
        }
    }

    private static Value value(InputStream in) {
        Value v = new Value();
        ValueKind kind = ValueKind.from_int(in.read_long()); // BAD_PARAM for a kind IDL does not know: refused
        switch (kind.value()) {
            case ValueKind._VK_BOOLEAN -> v.asBoolean(in.read_boolean());
            case ValueKind._VK_LONG -> v.asLong(in.read_longlong());
            case ValueKind._VK_DOUBLE -> v.asDouble(in.read_double());
            case ValueKind._VK_STRING -> v.asString(in.read_string());
            case ValueKind._VK_BYTES -> {
                byte[] bytes = new byte[length(in, 1, "a Bytes value")];
                in.read_octet_array(bytes, 0, bytes.length);
                v.asBytes(bytes);
            }
            case ValueKind._VK_DOUBLES -> {
                double[] doubles = new double[length(in, Double.BYTES, "a Doubles value")];
                in.read_double_array(doubles, 0, doubles.length);
                v.asDoubles(doubles);
            }
            default -> throw new MARSHAL(REFUSED + "value kind " + kind.value() + " is not read");
        }
        return v;
    }

    /** A sequence's length, refused when negative or when its elements could not fit in the bytes left. */
    private static int length(InputStream in, int minElementBytes, String what) {
        int claimed = in.read_long();
        int left = bytesLeft(in);
        if (claimed < 0 || (long) claimed * minElementBytes > left) {
            throw new MARSHAL(REFUSED + what + " claim " + claimed + " elements, but only "
                    + left + " bytes are left");
        }
        return claimed;
    }

    private static int bytesLeft(InputStream in) {
        try {
            return in.available();
        } catch (java.io.IOException unknown) {
            throw new MARSHAL(REFUSED + "the bytes left cannot be known: " + unknown.getMessage());
        }
    }

    private static MARSHAL refused(String why, RuntimeException cause) {
        MARSHAL refused = new MARSHAL(REFUSED + why);
        refused.initCause(cause);
        return refused;
    }
}

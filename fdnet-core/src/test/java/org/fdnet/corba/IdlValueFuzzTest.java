package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.util.Arrays;
import java.util.Objects;
import org.fdnet.corba.idl.SampledValue;
import org.fdnet.corba.idl.SampledValuesHelper;
import org.fdnet.corba.idl.Value;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.corba.idl.ValueBatchHelper;
import org.fdnet.corba.idl.ValueHelper;
import org.jacorb.orb.CDRInputStream;
import org.jacorb.orb.CDROutputStream;
import org.omg.CORBA.SystemException;

/**
 * Fuzzes the IDL values a host takes from the wire: CDR bytes read as a {@link ValueBatch} (a cross-host link's
 * values, first byte even) or as {@code SampledValues} (what a running network's listener receives, first byte
 * odd), then turned into Java and runtime values by {@link ValueCodec} and {@link IdlMapping}. Malformed bytes
 * must fail as JacORB's CORBA {@link SystemException} (MARSHAL, BAD_PARAM: the caller gets it as the call's
 * failure), never as another exception, an allocation of what the bytes merely claim, or a hang; every value
 * read must cross back: encoded, written and read again it is the same value. Seeds and kept findings:
 * {@code src/test/resources/org/fdnet/corba/IdlValueFuzzTestInputs/}.
 */
class IdlValueFuzzTest {

    @FuzzTest(maxDuration = "10m")
    void shouldDecodeOrRefuseTheValue(byte[] input) {
        if (input.length < 2) {
            return;
        }
        boolean bigEndian = (input[0] & 2) == 0;
        byte[] cdr = Arrays.copyOfRange(input, 1, input.length);
        Value[] values;
        try {
            values = (input[0] & 1) == 0 ? batch(cdr, bigEndian) : sampled(cdr, bigEndian);
        } catch (SystemException refused) {
            assertThat(refused.getMessage()).isNotNull();
            return;
        }
        for (Value v : values) {
            Object decoded = ValueCodec.decode(v);
            assertThat(ValueCodec.decodeRuntime(v)).isNotNull();
            Object again = ValueCodec.decode(crossed(ValueCodec.encode(decoded)));
            assertThat(Objects.deepEquals(again, decoded)).as("value %s crosses back", decoded).isTrue();
        }
    }

    private static Value[] batch(byte[] cdr, boolean bigEndian) {
        ValueBatch batch = ValueBatchHelper.read(new CDRInputStream(null, cdr, !bigEndian));
        assertThat(batch.originStream).isNotNull();
        return batch.values;
    }

    private static Value[] sampled(byte[] cdr, boolean bigEndian) {
        SampledValue[] sampled = SampledValuesHelper.read(new CDRInputStream(null, cdr, !bigEndian));
        Value[] values = new Value[sampled.length];
        for (int i = 0; i < sampled.length; i++) {
            assertThat(IdlMapping.ref(sampled[i].data)).isNotNull();
            values[i] = sampled[i].latest;
        }
        return values;
    }

    private static Value crossed(Value v) {
        CDROutputStream out = new CDROutputStream();
        ValueHelper.write(out, v);
        return ValueHelper.read(new CDRInputStream(null, out.getBufferCopy(), false));
    }
}

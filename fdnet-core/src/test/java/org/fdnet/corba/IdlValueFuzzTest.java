package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.util.Arrays;
import java.util.Objects;
import org.fdnet.corba.idl.SampledValue;
import org.fdnet.corba.idl.Value;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.corba.idl.ValueHelper;
import org.jacorb.orb.CDRInputStream;
import org.jacorb.orb.CDROutputStream;
import org.junit.jupiter.api.Test;
import org.omg.CORBA.MARSHAL;

/**
 * Fuzzes the IDL values a host takes from the wire: CDR bytes read as a {@link ValueBatch} (a cross-host link's
 * values, first byte even) or as {@code SampledValues} (what a running network's listener receives, first byte
 * odd), read as a host reads them ({@link CheckedValueReader}), then turned into Java and runtime values by
 * {@link ValueCodec} and {@link IdlMapping}. Malformed bytes must fail as the reader's {@link MARSHAL} (the caller
 * gets it as the call's failure), never as another exception, an allocation of what the bytes merely claim, or a hang; every value
 * read must cross back: encoded, written and read again it is the same value. Seeds and kept findings:
 * {@code src/test/resources/org/fdnet/corba/IdlValueFuzzTestInputs/}.
 */
class IdlValueFuzzTest {
    /** JacORB's ORB singleton: what a CDR stream needs to read (no threads, no ports). */
    private static final org.omg.CORBA.ORB ORB = org.omg.CORBA.ORB.init();

    @FuzzTest(maxDuration = "10m")
    void shouldDecodeOrRefuseTheValue(byte[] input) {
        if (input.length < 2) {
            return;
        }
        boolean littleEndian = (input[0] & 2) != 0;
        // Built outside the try: a stream that cannot be made is this test's failure, not a refused input.
        CDRInputStream in = new CDRInputStream(ORB, Arrays.copyOfRange(input, 1, input.length), littleEndian);
        Value[] values;
        try {
            values = (input[0] & 1) == 0 ? batch(in) : sampled(in);
        } catch (MARSHAL refused) {
            assertThat(refused.getMessage()).startsWith(CheckedValueReader.REFUSED);
            return;
        }
        for (Value v : values) {
            Object decoded = ValueCodec.decode(v);
            assertThat(ValueCodec.decodeRuntime(v)).isNotNull();
            Object again = ValueCodec.decode(crossed(ValueCodec.encode(decoded)));
            assertThat(Objects.deepEquals(again, decoded)).as("value %s crosses back", decoded).isTrue();
        }
    }

    /** Guards the target itself: a seed of every kind must decode, not be refused (else the fuzzer explores nothing). */
    @Test
    void shouldDecodeTheSeedOfEveryKind() throws Exception {
        byte[] seed;
        try (var in = getClass().getResourceAsStream("IdlValueFuzzTestInputs/shouldDecodeOrRefuseTheValue/batch-every-kind")) {
            seed = in.readAllBytes();
        }
        Value[] values = batch(new CDRInputStream(ORB, Arrays.copyOfRange(seed, 1, seed.length), false));
        assertThat(values).extracting(ValueCodec::decode).hasSize(6).contains(true, 42L, -0.5, "Certainty \u00fc");
    }

    private static Value[] batch(CDRInputStream in) {
        ValueBatch batch = CheckedValueReader.batch(in);
        assertThat(batch.originStream).isNotNull();
        return batch.values;
    }

    private static Value[] sampled(CDRInputStream in) {
        SampledValue[] sampled = CheckedValueReader.sampled(in);
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
        return ValueHelper.read(new CDRInputStream(ORB, out.getBufferCopy(), false));
    }
}

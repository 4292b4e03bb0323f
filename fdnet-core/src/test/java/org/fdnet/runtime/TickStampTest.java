package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.fdnet.runtime.TestNetworks.data;
import static org.fdnet.runtime.TestNetworks.quiet;
import static org.fdnet.runtime.TestNetworks.read;
import static org.fdnet.runtime.TestNetworks.ref;
import static org.fdnet.runtime.TestNetworks.relation;
import static org.fdnet.runtime.TestNetworks.start;
import static org.fdnet.runtime.TestNetworks.write;

import java.util.concurrent.atomic.AtomicLong;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.library.DoubleSensor;
import org.junit.jupiter.api.Test;

/**
 * Source ticks: a value carries the number of the newest sensor snapshot it was computed from; a Relation's
 * outputs get the newest tick of the inputs it read; several sensors can be pushed in one commit.
 */
class TickStampTest {
    /** Reads input 0 only (whatever else it is wired to) and writes it to every output. */
    public static class FirstInputOnly extends Relation {
        @Override
        protected void compute(RelationContext c) {
            Value v = c.input(0);
            if (v != null) {
                c.outputAll(Value.of(v.asDouble()));
            }
        }
    }

    /** Reads both inputs and counts the firings that saw them from different ticks. */
    public static class MixedTicks extends Relation {
        static final AtomicLong MIXED = new AtomicLong();
        static final AtomicLong FIRINGS = new AtomicLong();

        @Override
        protected void compute(RelationContext c) {
            Value a = c.input(0);
            Value b = c.input(1);
            FIRINGS.incrementAndGet();
            if (a != null && b != null && a.tick() != b.tick()) {
                MIXED.incrementAndGet();
            }
        }
    }

    private static NetworkInfo twoSensors(String relationClass, String... parameters) {
        NetworkInfo n = new NetworkInfo("ticks");
        n.addNode("main", data("Gyro", "DoubleSensor"));
        n.addNode("main", data("Tilt", "DoubleSensor"));
        n.addNode("main", data("Out", "DoubleData"));
        n.addNode("main", relation("Join", relationClass, parameters));
        read(n, "main", "Gyro", "Join");
        read(n, "main", "Tilt", "Join");
        write(n, "main", "Join", "Out");
        return n;
    }

    @Test
    void shouldStampARelationsOutputWithTheNewestTickOfItsInputs() throws Exception {
        try (RuntimeNetwork net = start(twoSensors("Expression", "expression=in0 + in1"), null)) {
            DoubleSensor gyro = net.dataInstance(ref("Gyro"), DoubleSensor.class);
            DoubleSensor tilt = net.dataInstance(ref("Tilt"), DoubleSensor.class);
            gyro.push(Value.of(1.0).withTick(5));
            tilt.push(Value.of(2.0).withTick(9));
            quiet(net);
            assertThat(net.controller().value(ref("Out")).asDouble()).isEqualTo(3.0);
            assertThat(net.controller().value(ref("Out")).tick()).isEqualTo(9);
            gyro.push(Value.of(1.5).withTick(12));
            quiet(net);
            assertThat(net.controller().value(ref("Out")).tick()).isEqualTo(12);
            assertThat(net.controller().value(ref("Gyro")).tick()).as("kept through the store").isEqualTo(12);
        }
    }

    @Test
    void shouldStampOnlyFromTheInputsARelationActuallyRead() throws Exception {
        try (RuntimeNetwork net = start(twoSensors(FirstInputOnly.class.getName()), null)) {
            DoubleSensor gyro = net.dataInstance(ref("Gyro"), DoubleSensor.class);
            DoubleSensor tilt = net.dataInstance(ref("Tilt"), DoubleSensor.class);
            gyro.push(Value.of(1.0).withTick(3));
            tilt.push(Value.of(2.0).withTick(40));
            quiet(net);
            assertThat(net.controller().value(ref("Out")).tick()).as("Tilt is wired but never read").isEqualTo(3);
            net.controller().setValue(ref("Gyro"), Value.of(4.0));
            quiet(net);
            assertThat(net.controller().value(ref("Out")).tick()).as("computed from no snapshot").isZero();
        }
    }

    @Test
    void shouldPushSeveralSensorsInOneCommitSoNoRelationMixesTwoSnapshots() throws Exception {
        try (RuntimeNetwork net = start(twoSensors(MixedTicks.class.getName()), null)) {
            SensorData[] sensors = {net.dataInstance(ref("Gyro"), DoubleSensor.class),
                net.dataInstance(ref("Tilt"), DoubleSensor.class)};
            Value[] values = new Value[2];
            MixedTicks.MIXED.set(0);
            for (long tick = 1; tick <= 200; tick++) {
                values[0] = Value.of(0.1 * tick).withTick(tick);
                values[1] = Value.of(0.2 * tick).withTick(tick);
                SensorData.pushTogether(sensors, values);
                assertThat(values).as("cleared for the next snapshot").containsOnlyNulls();
            }
            quiet(net);
            assertThat(MixedTicks.MIXED.get()).as("firings that saw two snapshots at once").isZero();
            assertThat(net.controller().value(ref("Tilt")).tick()).isEqualTo(200);

            for (long tick = 201; tick <= 400; tick++) { // one at a time, as before: the reader sees halves
                sensors[0].push(Value.of(0.1).withTick(tick));
                sensors[1].push(Value.of(0.2).withTick(tick));
            }
            quiet(net);
            assertThat(MixedTicks.MIXED.get()).as("separate pushes do mix").isPositive();
        }
    }

    @Test
    void shouldRefuseToPushSensorsOfTwoNetworksTogether() throws Exception {
        try (RuntimeNetwork a = start(twoSensors(FirstInputOnly.class.getName()), null);
             RuntimeNetwork b = start(twoSensors(FirstInputOnly.class.getName()), null)) {
            SensorData[] sensors = {a.dataInstance(ref("Gyro"), DoubleSensor.class),
                b.dataInstance(ref("Gyro"), DoubleSensor.class)};
            assertThatThrownBy(() -> SensorData.pushTogether(sensors, new Value[] {Value.of(1.0), Value.of(2.0)}))
                    .hasMessageContaining("another network");
        }
    }
}

package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.fdnet.runtime.TestNetworks.*;

import java.util.List;
import org.fdnet.event.ValueType;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeStartException;
import org.fdnet.runtime.library.DoubleSensor;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class ProgrammingModelTest {

    @Test
    void shouldConvertValuesBetweenTypesAndKeepTheirTextForm() {
        assertThat(Value.of(3L).convertTo(ValueType.DOUBLE).asDouble()).isEqualTo(3.0);
        assertThat(Value.of(true).asDouble()).isEqualTo(1.0);
        assertThat(Value.of(2.5).convertTo(ValueType.DOUBLES).asDoubles()).containsExactly(2.5);
        assertThat(Value.ofDoubles(1, 2, 3).text()).isEqualTo("1.0,2.0,3.0");
        assertThat(Value.parse(ValueType.DOUBLES, "1.0,2.0,3.0").asDoubles()).containsExactly(1, 2, 3);
        assertThat(Value.parse(ValueType.BYTES, Value.ofBytes(new byte[] {1, 2}).text()).asBytes()).containsExactly(1, 2);
        assertThatThrownBy(() -> Value.ofDoubles(1, 2).asDouble()).hasMessageContaining("vector of 2");
    }

    @Test
    void shouldNotLetAnyoneChangeAPublishedVector() {
        double[] posture = {0.3, 0.3};
        Value v = Value.ofDoubles(posture);
        posture[0] = 9;
        v.asDoubles()[1] = 9;
        assertThat(v.asDoubles()).containsExactly(0.3, 0.3);
    }

    @Test
    void shouldNameTheNodeParameterAndValueWhenAParameterIsWrong() {
        NodeParameters p = new NodeParameters(new NodeRef("Walk", "gait"), List.of(Parameter.named("gain", "fast")));
        assertThatThrownBy(() -> p.requireDouble("gain"))
                .isInstanceOf(ParameterException.class)
                .hasMessage("module 'Walk', node 'gait': parameter 'gain' must be a number, was 'fast'");
        assertThatThrownBy(() -> p.requireLong("period")).hasMessageContaining("module 'Walk', node 'gait': parameter 'period' is required");
    }

    @Test
    void shouldRefuseToStartWithABadParameterNamingTheNode() {
        NetworkInfo n = new NetworkInfo("bad");
        n.addNode("main", data("Out", "DoubleData"));
        n.addNode("main", relation("Filter", "LowPass", "alpha=2.5"));
        write(n, "main", "Filter", "Out");
        assertThatThrownBy(() -> start(n, null))
                .isInstanceOf(RuntimeStartException.class)
                .hasMessageContaining("module 'main', node 'Filter': parameter 'alpha' must be a number in (0, 1], was 2.5");
    }

    @Test
    void shouldUseTypedParametersAsTheFileDeclaresThem() throws Exception {
        NetworkInfo n = new NetworkInfo("typed");
        n.addNode("main", new org.fdnet.netinfo.NodeInfo(org.fdnet.netinfo.NodeKind.DATA, "Posture", "localhost", "",
                LIB + "DoublesData", List.of(new Parameter("length", ParameterType.LONG, "3"),
                new Parameter("initial", ParameterType.DOUBLES, "0.1 0.2 0.3"))));
        try (RuntimeNetwork net = start(n, null)) {
            assertThat(net.controller().value(ref("Posture")).asDoubles()).containsExactly(0.1, 0.2, 0.3);
            assertThatThrownBy(() -> net.controller().setValue(ref("Posture"), "1 2"))
                    .hasMessageContaining("main/Posture").hasMessageContaining("3 are expected");
            assertThat(net.controller().value(ref("Posture")).asDoubles()).containsExactly(0.1, 0.2, 0.3);
        }
    }

    @Test
    void shouldLetASensorDataPushValuesFromOutside() throws Exception {
        NetworkInfo n = new NetworkInfo("sensor");
        n.addNode("main", data("Gyro", "DoubleSensor"));
        n.addNode("main", data("Scaled", "DoubleData"));
        n.addNode("main", relation("Scale", "Expression", "expression=100 * in0"));
        read(n, "main", "Gyro", "Scale");
        write(n, "main", "Scale", "Scaled");
        try (RuntimeNetwork net = start(n, null)) {
            // the instance the network made, as a device driver gets it
            DoubleSensor sensor = net.dataInstance(ref("Gyro"), DoubleSensor.class);
            sensor.push(0.25);
            quiet(net);
            assertThat(net.controller().value(ref("Scaled")).asDouble()).isEqualTo(25.0);
            assertThat(net.controller().value(ref("Gyro")).time()).isPositive();
            assertThatThrownBy(() -> net.dataInstance(ref("Scaled"), DoubleSensor.class)).hasMessageContaining("not a");
        }
    }

    @Test
    void shouldCoerceWritesToTheDataTypeAndClampToItsBounds() throws Exception {
        NetworkInfo n = new NetworkInfo("clamp");
        n.addNode("main", data("Speed", "DoubleData", "min=0", "max=1"));
        try (RuntimeNetwork net = start(n, null)) {
            net.controller().setValue(ref("Speed"), Value.of(7L));
            assertThat(net.controller().value(ref("Speed")).asDouble()).isEqualTo(1.0);
            assertThatThrownBy(() -> net.controller().setValue(ref("Speed"), "fast"))
                    .hasMessageContaining("main/Speed");
        }
    }
}

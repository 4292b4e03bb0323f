package org.fdnet.roq.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.TimeUnit;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.event.ValueType;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.roq.sim.LoopStatistics;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.view.DemoFigures;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The demo's figures: the margin from KeepBalance's reports, a Probing module's counters by name, or n/a. */
@Timeout(value = 30, unit = TimeUnit.SECONDS)
class DemoMeterTest {
    private static final String DOUBLE = "org.fdnet.runtime.library.DoubleData";

    @Test
    void shouldTakeTheMarginFromReportsAndTheSmallestSoFar() throws Exception {
        DemoMeter meter = new DemoMeter(null);
        meter.accept(new RelationValueEvent(3, 1, "margin 0.120 m"));
        meter.accept(new RelationValueEvent(3, 2, "margin -0.031 m (below 0.05)"));
        meter.accept(new RelationValueEvent(3, 3, "margin 0.090 m"));
        meter.accept(new RelationValueEvent(4, 4, "walking"));
        try (RuntimeNetwork net = RuntimeNetwork.start(plain(), RuntimeOptions.defaults())) {
            meter.lookUpCounters(net);
            DemoFigures f = meter.figures(net, new SensorSnapshot(), 0, new LoopStatistics(), false);
            assertThat(f.margin()).isEqualTo(0.090);
            assertThat(f.smallestMargin()).isEqualTo(-0.031);
            assertThat(f.events()).isEqualTo(4);
            assertThat(f.probes()).as("no Probing Datas: n/a").isNegative();
            assertThat(f.progressLine()).contains("margin 0.090 m", "probes n/a", "fragile found n/a avoided n/a");
        }
    }

    @Test
    void shouldReadProbesAndFragileCellsFromDatasByName() throws Exception {
        NetworkInfo n = plain();
        n.addModule("Probing", true);
        n.addNode("Probing", NodeInfo.data("probes", DOUBLE));
        n.addNode("Probing", NodeInfo.data("fragile found", DOUBLE));
        n.addNode("Probing", NodeInfo.data("fragile avoided", DOUBLE));
        try (RuntimeNetwork net = RuntimeNetwork.start(n, RuntimeOptions.defaults())) {
            DemoMeter meter = new DemoMeter(null);
            meter.lookUpCounters(net);
            net.controller().setValue(new NodeRef("Probing", "probes"), Value.of(7.0));
            net.controller().setValue(new NodeRef("Probing", "fragile found"), Value.of(2.0));
            net.controller().setValue(new NodeRef("Probing", "fragile avoided"), Value.of(1.0));
            DemoFigures f = meter.figures(net, new SensorSnapshot(), 0, new LoopStatistics(), false);
            assertThat(f.probes()).isEqualTo(7);
            assertThat(f.fragileFound()).isEqualTo(2);
            assertThat(f.fragileAvoided()).isEqualTo(1);
            assertThat(f.margin()).as("no report yet").isNaN();
            assertThat(f.progressLine()).contains("margin n/a", "probes 7", "fragile found 2 avoided 1");
        }
    }

    @Test
    void shouldPreferTheValuesOfTheMarginDataToTheReportsLeavingOutItsInitialValue() throws Exception {
        DemoMeter meter = new DemoMeter(null);
        meter.accept(new NodeNamedEvent(5, 1, NodeKind.DATA, new NodeRef("Balance", "margin")));
        meter.accept(new DataValueEvent(5, 1, ValueType.DOUBLE, "0.0")); // the Data's initial value, not a margin
        meter.accept(new DataValueEvent(5, 2, ValueType.DOUBLE, "0.081"));
        meter.accept(new RelationValueEvent(3, 3, "margin 0.500 m"));
        meter.accept(new DataValueEvent(5, 4, ValueType.DOUBLE, "-0.012"));
        meter.accept(new DataValueEvent(5, 5, ValueType.DOUBLE, "0.064"));
        meter.accept(new DataValueEvent(6, 6, ValueType.DOUBLE, "-0.9"));
        try (RuntimeNetwork net = RuntimeNetwork.start(plain(), RuntimeOptions.defaults())) {
            DemoFigures f = meter.figures(net, new SensorSnapshot(), 0, new LoopStatistics(), false);
            assertThat(f.margin()).isEqualTo(0.064);
            assertThat(f.smallestMargin()).as("smallest of the margin Data's values after its initial one")
                    .isEqualTo(-0.012);
        }
    }

    private static NetworkInfo plain() {
        NetworkInfo n = new NetworkInfo("meter");
        n.addNode("main", NodeInfo.data("speed", DOUBLE));
        return n;
    }
}

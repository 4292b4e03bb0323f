package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.fdnet.runtime.TestNetworks.*;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

@Timeout(30)
class ControllerTest {
    @TempDir
    Path dir;

    private static NetworkInfo network() {
        NetworkInfo n = new NetworkInfo("live");
        n.addNode("main", data("In", "DoubleData"));
        n.addNode("main", data("Out", "DoubleData"));
        n.addNode("main", relation("Gain", "Expression", "expression=3 * in0"));
        read(n, "main", "In", "Gain");
        write(n, "main", "Gain", "Out");
        return n;
    }

    @Test
    void shouldApplyALiveEditAndRunWhatItAdds() throws Exception {
        try (RuntimeNetwork net = start(network(), null)) {
            Controller c = net.controller();
            List<ChangeOutcome> settled = new CopyOnWriteArrayList<>();
            c.addChangeListener(settled::add);
            ChangeOutcome o = c.apply("add an offset", NetworkEdits.all(
                    NetworkEdits.addNode("main", data("Shifted", "DoubleData")),
                    NetworkEdits.addNode("main", relation("Offset", "Expression", "expression=in0 + 1")),
                    NetworkEdits.addConnection("main", ConnectionInfo.reader(ref("Out"), ref("Offset"))),
                    NetworkEdits.addConnection("main", ConnectionInfo.writer(ref("Offset"), ref("Shifted")))));
            assertThat(o.executed()).isTrue();
            assertThat(settled).containsExactly(o);
            c.setValue(ref("In"), "2");
            quiet(net);
            assertThat(c.value(ref("Shifted")).asDouble()).isEqualTo(7.0);
        }
    }

    @Test
    void shouldRefuseABadEditSayWhyAndLeaveTheNetworkUntouched() throws Exception {
        try (RuntimeNetwork net = start(network(), null)) {
            Controller c = net.controller();
            NetworkInfo before = c.snapshot();
            // the second half names a class that does not exist: nothing of the first half may remain
            ChangeOutcome o = c.apply("add two", NetworkEdits.all(
                    NetworkEdits.addNode("main", data("Fine", "DoubleData")),
                    NetworkEdits.addNode("main", relation("Broken", "NoSuchRelation"))));
            assertThat(o.executed()).isFalse();
            assertThat(o.reason()).contains("node 'Broken'").contains("NoSuchRelation");
            assertThat(c.snapshot()).isEqualTo(before);
            assertThat(c.value(ref("Fine"))).isNull();
            ChangeOutcome dup = c.apply("duplicate", NetworkEdits.addNode("main", data("In", "DoubleData")));
            assertThat(dup.reason()).contains("already has a node named 'In'");
            ChangeOutcome badParam = c.setParameter(ref("Gain"), "expression", "3 *");
            assertThat(badParam.executed()).isFalse();
            assertThat(badParam.reason()).contains("module 'main', node 'Gain': parameter 'expression' must be an expression of the inputs");
            assertThat(c.snapshot()).isEqualTo(before);
            c.setValue(ref("In"), "1");
            quiet(net);
            assertThat(c.value(ref("Out")).asDouble()).isEqualTo(3.0);
        }
    }

    @Test
    void shouldRestartARelationWithANewParameterAndKeepDataValuesOnAParameterChange() throws Exception {
        try (RuntimeNetwork net = start(network(), null)) {
            Controller c = net.controller();
            c.setValue(ref("In"), "2");
            quiet(net);
            assertThat(c.setParameter(ref("Gain"), "expression", "10 * in0").executed()).isTrue();
            quiet(net);
            assertThat(c.value(ref("Out")).asDouble()).isEqualTo(20.0);
            assertThat(c.setParameter(ref("In"), "max", "100").executed()).isTrue();
            assertThat(c.value(ref("In")).asDouble()).isEqualTo(2.0);
        }
    }

    @Test
    void shouldRefuseSettingAValueThatDoesNotFitNamingTheData() throws Exception {
        try (RuntimeNetwork net = start(network(), null)) {
            assertThatThrownBy(() -> net.controller().setValue(ref("In"), "abc")).hasMessageContaining("main/In");
            assertThatThrownBy(() -> net.controller().setValue(ref("Gain"), "1")).hasMessageContaining("main/Gain is not a Data");
            assertThatThrownBy(() -> net.controller().setValue(ref("Nope"), "1")).hasMessageContaining("main/Nope");
        }
    }

    @Test
    void shouldSnapshotTheRunningNetworkSoItCanBeSavedAndRunAgain() throws Exception {
        Path file = dir.resolve("saved.fdn");
        try (RuntimeNetwork net = start(network(), null)) {
            Controller c = net.controller();
            c.apply("add module", NetworkEdits.addModule("Later", false));
            c.apply("add node", NetworkEdits.addNode("Later", data("Note", "StringData", "initial=hello")));
            NetworkRepository.save(c.snapshot(), file);
        }
        NetworkInfo reloaded = NetworkRepository.load(file);
        assertThat(reloaded.module("Later").node("Note").kind()).isEqualTo(NodeKind.DATA);
        try (RuntimeNetwork again = start(reloaded, null)) {
            again.controller().setValue(ref("In"), "5");
            quiet(again);
            assertThat(again.controller().value(ref("Out")).asDouble()).isEqualTo(15.0);
            assertThat(again.controller().load("Later").executed()).isTrue();
            assertThat(again.controller().value(ref("Later/Note")).text()).isEqualTo("hello");
        }
    }

    @Test
    void shouldMakeStandInsForRemoteDatasAndReportTheLinkWithoutCrashing() throws Exception {
        NetworkInfo n = network();
        n.addNode("main", new NodeInfo(NodeKind.DATA, "Far", "robot-2", "", LIB + "DoubleData", List.of()));
        n.addNode("main", new NodeInfo(NodeKind.RELATION, "FarAway", "robot-2", "", LIB + "Expression",
                List.of(org.fdnet.netinfo.Parameter.named("expression", "in0"))));
        read(n, "main", "Far", "Gain");
        read(n, "main", "Out", "FarAway");
        RuntimeOptions o = options().placement(Placement.thisHost());
        try (RuntimeNetwork net = RuntimeNetwork.start(n, o)) {
            Controller c = net.controller();
            assertThat(c.remoteLinks()).hasSize(2);
            assertThat(c.remoteLinks()).anySatisfy(l -> {
                assertThat(l.remoteEnd()).isEqualTo("data");
                assertThat(l.standIn()).isTrue();
                assertThat(l.remoteHost()).isEqualTo("robot-2");
            });
            assertThat(c.relationState(ref("FarAway"))).isNull();
            // a distribution layer feeds the stand-in; the local Relation sees it as an input
            c.setValue(ref("Far"), "4");
            c.setValue(ref("In"), "1");
            quiet(net);
            assertThat(c.relationState(ref("Gain")).status()).isEqualTo(RelationStatus.RUNNING);
        }
    }
}

package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.fdnet.runtime.TestNetworks.*;

import java.util.List;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.event.NetworkCommand;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class ModulesTest {

    /** main has Clock; Arm (loaded at start) reads it; Tool (not loaded at start) reads Arm's output. */
    private static NetworkInfo network() {
        NetworkInfo n = new NetworkInfo("modules");
        n.addNode("main", data("Clock", "DoubleData"));
        n.addNode("main", data("Mirror", "DoubleData"));
        n.addNode("main", relation("Reflect", "Expression", "expression=-in0"));
        n.addModule("Arm", true);
        n.addNode("Arm", data("Shoulder", "DoubleData"));
        n.addNode("Arm", relation("Plan", "Expression", "expression=2 * in0"));
        read(n, "Arm", "Clock", "Plan");
        write(n, "Arm", "Plan", "Shoulder");
        // declared in main, joining main and Arm: the cross-module connection of Figure 32
        read(n, "main", "Arm/Shoulder", "Reflect");
        write(n, "main", "Reflect", "Mirror");
        n.addModule("Tool", false);
        n.addNode("Tool", data("Grip", "DoubleData"));
        n.addNode("Tool", relation("Close", "Expression", "expression=in0 + 100"));
        read(n, "Tool", "Arm/Shoulder", "Close");
        write(n, "Tool", "Close", "Grip");
        return n;
    }

    @Test
    void shouldLoadOnlyModulesMarkedLoadAtStart() throws Exception {
        try (RuntimeNetwork net = start(network(), null)) {
            assertThat(net.controller().loadedModules()).containsExactly("main", "Arm");
            assertThat(net.controller().value(ref("Tool/Grip"))).isNull();
            net.controller().setValue(ref("Clock"), "3");
            quiet(net);
            assertThat(net.controller().value(ref("Mirror")).asDouble()).isEqualTo(-6.0);
        }
    }

    @Test
    void shouldDropCrossModuleConnectionsOnUnloadAndRemakeThemOnLoad() throws Exception {
        MemoryEventSink sink = new MemoryEventSink();
        try (RuntimeNetwork net = start(network(), sink)) {
            Controller c = net.controller();
            assertThat(c.unload("Arm").executed()).isTrue();
            RelationState reflect = c.relationState(ref("Reflect"));
            assertThat(reflect.status()).isEqualTo(RelationStatus.WAITING);
            assertThat(reflect.missing()).containsExactly(ref("Arm/Shoulder"));
            assertThat(reflect.text()).isEqualTo("WAITING: missing Arm/Shoulder");
            assertThat(sink.events(NetworkCommandEvent.class)).extracting(NetworkCommandEvent::command)
                    .contains(NetworkCommand.UNLOAD, NetworkCommand.DISCONNECT, NetworkCommand.DESTROY);
            // main runs on without Arm
            c.setValue(ref("Clock"), "5");
            quiet(net);
            assertThat(c.value(ref("Arm/Shoulder"))).isNull();
            // load again: the connection declared in main comes back by itself, and values flow
            int connectsBefore = count(sink, NetworkCommand.CONNECT);
            assertThat(c.load("Arm").executed()).isTrue();
            assertThat(count(sink, NetworkCommand.CONNECT) - connectsBefore).isEqualTo(3);
            assertThat(c.relationState(ref("Reflect")).status()).isEqualTo(RelationStatus.RUNNING);
            c.setValue(ref("Clock"), "7");
            quiet(net);
            assertThat(c.value(ref("Mirror")).asDouble()).isEqualTo(-14.0);
        }
    }

    @Test
    void shouldLoadAModuleWhoseDependenciesAreMissingAndLetItsRelationsReportIt() throws Exception {
        try (RuntimeNetwork net = start(network(), null)) {
            Controller c = net.controller();
            c.unload("Arm");
            assertThat(c.load("Tool").executed()).isTrue();
            RelationState close = c.relationState(ref("Tool/Close"));
            assertThat(close.status()).isEqualTo(RelationStatus.WAITING);
            assertThat(close.missing()).containsExactly(ref("Arm/Shoulder"));
            c.load("Arm");
            c.setValue(ref("Clock"), "1");
            quiet(net);
            assertThat(c.relationState(ref("Tool/Close")).status()).isEqualTo(RelationStatus.RUNNING);
            assertThat(c.value(ref("Tool/Grip")).asDouble()).isEqualTo(102.0);
        }
    }

    @Test
    void shouldHoldAModuleWithoutDeletingItAndCatchUpOnResume() throws Exception {
        try (RuntimeNetwork net = start(network(), null)) {
            Controller c = net.controller();
            c.setValue(ref("Clock"), "1");
            quiet(net);
            assertThat(c.hold("Arm").executed()).isTrue();
            assertThat(c.relationState(ref("Arm/Plan")).status()).isEqualTo(RelationStatus.HELD);
            long firings = c.relationState(ref("Arm/Plan")).firings();
            c.setValue(ref("Clock"), "4");
            quiet(net);
            assertThat(c.relationState(ref("Arm/Plan")).firings()).isEqualTo(firings);
            assertThat(c.value(ref("Arm/Shoulder")).asDouble()).isEqualTo(2.0);
            assertThat(c.resume("Arm").executed()).isTrue();
            quiet(net);
            assertThat(c.value(ref("Arm/Shoulder")).asDouble()).isEqualTo(8.0);
            assertThat(c.relationState(ref("Arm/Plan")).status()).isEqualTo(RelationStatus.RUNNING);
        }
    }

    @Test
    void shouldRefuseModuleRequestsThatMakeNoSense() throws Exception {
        try (RuntimeNetwork net = start(network(), null)) {
            Controller c = net.controller();
            assertThat(c.unload("main").reason()).contains("always loaded");
            assertThat(c.load("Arm").reason()).contains("already loaded");
            assertThat(c.load("Nope").reason()).contains("no module named 'Nope'");
            assertThat(c.resume("Arm").reason()).contains("not on hold");
        }
    }

    @Test
    void shouldKeepObserversThroughUnloadAndLoad() throws Exception {
        try (RuntimeNetwork net = start(network(), null)) {
            Controller c = net.controller();
            List<Double> seen = new java.util.concurrent.CopyOnWriteArrayList<>();
            c.observe(ref("Arm/Shoulder"), (d, id, v) -> seen.add(v.asDouble()));
            c.unload("Arm");
            c.load("Arm");
            c.setValue(ref("Clock"), "10");
            quiet(net);
            assertThat(seen).contains(20.0);
        }
    }

    private static int count(MemoryEventSink sink, NetworkCommand command) {
        return (int) sink.events(NetworkCommandEvent.class).stream().filter(e -> e.command() == command).count();
    }
}

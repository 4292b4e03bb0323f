package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.stream.Collectors;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.fdnet.runtime.engine.DrivenClock;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** A running engine's worker pool resized (a host sized for each run deployed on it): threads start and stop. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class WorkerResizeTest {
    private static final NodeRef LEVEL = new NodeRef("main", "Level");

    @Test
    void shouldStartAndRetireWorkerThreadsWhileTheNetworkRunsOn() throws Exception {
        Set<Thread> before = workerThreads();
        try (RuntimeNetwork net = RuntimeNetwork.start(ticking(), RuntimeOptions.defaults().workerThreads(2))) {
            assertThat(newWorkers(before)).hasSize(2);

            net.resizeWorkers(4);
            assertThat(net.workerThreads()).isEqualTo(4);
            assertThat(newWorkers(before)).hasSize(4);

            net.resizeWorkers(1);
            assertThat(net.workerThreads()).isEqualTo(1);
            long deadline = System.currentTimeMillis() + 5_000;
            while (newWorkers(before).size() > 1 && System.currentTimeMillis() < deadline) {
                Thread.sleep(10);
            }
            assertThat(newWorkers(before)).as("retired workers stop").hasSize(1);

            double first = net.controller().value(LEVEL).asDouble();
            Thread.sleep(300);
            assertThat(net.controller().value(LEVEL).asDouble()).as("the network runs on").isGreaterThan(first);
        }
        assertThat(newWorkers(before)).as("closed: no worker left").isEmpty();
    }

    @Test
    void shouldRunTheWorkerStartActionFirstOnEveryWorkerAlsoOnesStartedByAResize() throws Exception {
        Set<String> started = java.util.concurrent.ConcurrentHashMap.newKeySet();
        Set<Thread> before = workerThreads();
        try (RuntimeNetwork net = RuntimeNetwork.start(ticking(), RuntimeOptions.defaults().workerThreads(2)
                .workerStart(() -> {
                    started.add(Thread.currentThread().getName());
                    throw new IllegalStateException("a failing start action leaves the worker working");
                }))) {
            net.resizeWorkers(3);
            long deadline = System.currentTimeMillis() + 5_000;
            while (started.size() < 3 && System.currentTimeMillis() < deadline) {
                Thread.sleep(10);
            }
            assertThat(started).as("each worker ran it, on itself")
                    .isEqualTo(newWorkers(before).stream().map(Thread::getName).collect(Collectors.toSet()));
            assertThat(started).hasSize(3);
            double first = net.controller().value(LEVEL).asDouble();
            Thread.sleep(300);
            assertThat(net.controller().value(LEVEL).asDouble()).as("the workers fire on").isGreaterThan(first);
        }
    }

    @Test
    void shouldRefuseAPoolOfNoneAndADrivenNetworksPool() throws Exception {
        try (RuntimeNetwork net = RuntimeNetwork.start(ticking(), RuntimeOptions.defaults().workerThreads(1))) {
            assertThatThrownBy(() -> net.resizeWorkers(0)).isInstanceOf(IllegalArgumentException.class)
                    .hasMessageContaining("at least 1, was 0");
        }
        try (RuntimeNetwork driven = RuntimeNetwork.start(ticking(),
                RuntimeOptions.defaults().drivenClock(new DrivenClock(0)))) {
            assertThatThrownBy(() -> driven.resizeWorkers(2)).isInstanceOf(IllegalStateException.class)
                    .hasMessageContaining("driven clock");
        }
    }

    /** Source writes the engine's seconds into Level every 10 ms: ticks go through the pool. */
    private static NetworkInfo ticking() {
        NetworkInfo n = new NetworkInfo("ticking");
        n.addNode("main", new NodeInfo(NodeKind.DATA, "Level", "localhost", "", "DoubleData", List.of()));
        n.addNode("main", new NodeInfo(NodeKind.RELATION, "Source", "localhost", "", "Expression",
                List.of(Parameter.named("expression", "t"), new Parameter("period", ParameterType.LONG, "10"))));
        n.addConnection("main", ConnectionInfo.writer(new NodeRef("main", "Source"), LEVEL));
        return n;
    }

    private static Set<Thread> workerThreads() {
        return Thread.getAllStackTraces().keySet().stream()
                .filter(t -> t.isAlive() && t.getName().startsWith("fdnet-worker-")).collect(Collectors.toSet());
    }

    private static Set<Thread> newWorkers(Set<Thread> before) {
        Set<Thread> now = workerThreads();
        now.removeAll(before);
        return now;
    }
}

package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.event.RunIdentity;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A run's trace of another host (a child {@code fdnet host flyer}): read over CORBA, each line named by its host; a
 * reader that keeps up sees every value in order, and one far too slow costs lines — dropped and counted on the
 * host — never the host's progress.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class TraceAcrossHostsTest {
    private static final NodeRef LEVEL = new NodeRef("main", "Level");

    private CorbaCluster cluster;
    private NetworkDeployment deployment;
    private TraceCollector collector;

    @BeforeEach
    void startFlyer() {
        cluster = CorbaCluster.start();
        cluster.startHost("flyer");
    }

    @AfterEach
    void stop() {
        if (collector != null) {
            collector.close();
        }
        if (deployment != null) {
            deployment.close();
        }
        cluster.close();
    }

    @Test
    void shouldShowEveryValueOfTheOtherHostInOrderWhenTheReaderKeepsUp() throws Exception {
        Lines lines = new Lines(0);
        deploy(20, 10_000, lines);
        Thread.sleep(2_000);
        collector.close();

        List<Double> values = lines.valuesOf("flyer", "value    main/Level = ");
        assertThat(values).as(lines.text()).hasSizeGreaterThan(20);
        for (int i = 1; i < values.size(); i++) {
            assertThat(values.get(i)).as("value %d of %d", i, values.size()).isGreaterThan(values.get(i - 1));
        }
        assertThat(lines.hosts).containsOnly("flyer");
        assertThat(lines.text()).contains("named    #").contains("relation main/Source RUNNING");
        assertThat(lines.dropped).hasValue(0);
    }

    @Test
    void shouldDropAndCountOnTheHostWhatASlowReaderCannotTakeAndLetTheHostRunOn() throws Exception {
        Lines lines = new Lines(20); // 20 ms a line: at most 50 lines a second against the host's ~500 values
        deploy(2, 50, lines);
        Object before = read(LEVEL);
        Thread.sleep(3_000);
        Object after = read(LEVEL);
        collector.close();

        assertThat(lines.dropped.get()).as(lines.text()).isGreaterThan(100);
        assertThat(collector.droppedOn("flyer")).isEqualTo(lines.dropped.get());
        // the host ran on at its own pace: Level (its engine's seconds) moved on by far more than the lines shown
        assertThat((Double) after - (Double) before).isGreaterThan(2.0);
        assertThat(lines.count()).isPositive();
    }

    /** Source on the flyer writes its engine's seconds into Level every {@code periodMillis}; the flyer traced. */
    private void deploy(long periodMillis, int capacity, TraceOutput output) throws Exception {
        NetworkInfo n = new NetworkInfo("traced");
        n.addNode("main", new NodeInfo(NodeKind.DATA, "Level", "flyer", "", "DoubleData", List.of()));
        n.addNode("main", new NodeInfo(NodeKind.RELATION, "Source", "flyer", "", "Expression",
                List.of(Parameter.named("expression", "t"),
                        new Parameter("period", ParameterType.LONG, Long.toString(periodMillis)))));
        n.addConnection("main", ConnectionInfo.writer(new NodeRef("main", "Source"), LEVEL));
        DeploymentPlan plan = DeploymentPlan.of(n, "test", Set.of());
        RunIdentity run = RunIdentity.start("traced", "<cnet/>", List.copyOf(plan.hosts()));
        deployment = NetworkDeployment.start(plan, cluster.directory(), Map.of(), DeploymentListener.quiet(),
                new MemoryEventSink(), 4, 10_000, 100, new RunRecording(run, "", 0, capacity));
        collector = TraceCollector.start(deployment, output);
    }

    private Object read(NodeRef data) throws Exception {
        return ValueCodec.decode(deployment.host("flyer").read(IdlMapping.id(data)));
    }

    /** Trace lines as they come, each after {@code millisPerLine} (a slow terminal). */
    private static final class Lines implements TraceOutput {
        private final long millisPerLine;
        private final List<String> lines = new ArrayList<>();
        final Set<String> hosts = java.util.concurrent.ConcurrentHashMap.newKeySet();
        final AtomicLong dropped = new AtomicLong();

        Lines(long millisPerLine) {
            this.millisPerLine = millisPerLine;
        }

        @Override
        public void line(String host, long timeMicros, String text) {
            hosts.add(host);
            synchronized (lines) {
                lines.add(host + " " + text);
            }
            if (millisPerLine > 0) {
                try {
                    Thread.sleep(millisPerLine);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }

        @Override
        public void dropped(String host, long count) {
            assertThat(host).isEqualTo("flyer");
            dropped.addAndGet(count);
        }

        int count() {
            synchronized (lines) {
                return lines.size();
            }
        }

        String text() {
            synchronized (lines) {
                return String.join("\n", lines.subList(0, Math.min(lines.size(), 50)));
            }
        }

        List<Double> valuesOf(String host, String prefix) {
            List<Double> values = new ArrayList<>();
            synchronized (lines) {
                for (String l : lines) {
                    if (l.startsWith(host + " " + prefix)) {
                        values.add(Double.parseDouble(l.substring(host.length() + 1 + prefix.length())));
                    }
                }
            }
            return values;
        }
    }
}

package org.fdnet.roq.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.corba.control.RemoteLiveNetwork;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.viewer.data.NodeSelection;
import org.fdnet.viewer.data.PlotData;
import org.fdnet.viewer.source.LoggerConnection;
import org.fdnet.viewer.source.Replay;
import org.fdnet.viewer.source.ReplayLoader;
import org.fdnet.viewer.source.RunInfo;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Issue 11's "Done when", end to end against a real {@code fdnet demo} process (its own embedded logger on a
 * PostgreSQL of its own: the child's home is a temporary folder): attached through the control object, the tool
 * learns where the demo's logger serves viewers; the viewer's logger client receives live values of RoQ's posture
 * and of Balance's output; a Balance parameter set through the control object changes those values; Balance is
 * unloaded (its values stop) and loaded again (they flow again); the recorded run's last seconds replay.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class DemoLiveWalkthroughTest {
    private static final NodeRef KEEP_BALANCE = new NodeRef("Balance", "keep balance");
    private static final String SHIFT = "Balance/balance shift";
    private static final String POSTURE = "main/attitude";

    @Test
    void shouldLetAnAttachedToolFindTheLoggerPlotPostureAndBalanceChangeBalanceUnloadReloadAndReplay(@TempDir Path home)
            throws Exception {
        int controlPort = FdnetChildProcess.freePort();
        try (FdnetChildProcess demo = FdnetChildProcess.start("demo", List.of("-Duser.home=" + home),
                List.of("demo", "--for", "30s", "--network", RunOnSimulatorTest.WALK, "--course", "flat", "--control-port",
                        Integer.toString(controlPort)), "logger for viewers:", 60_000);
             RemoteLiveNetwork roq = RemoteLiveNetwork.attach("127.0.0.1:" + controlPort, null)) {
            String printed = demo.output().stream().filter(l -> l.startsWith("logger for viewers:")).findFirst()
                    .orElseThrow();
            Optional<String> logger = roq.loggerViewerAddress();
            assertThat(logger).as("the logger's viewer address through the control object").isPresent();
            assertThat(printed).as("the line the demo printed").contains(logger.get() + ", run ");

            Heard heard = new Heard();
            try (LoggerConnection viewer = new LoggerConnection(logger.get(), new PlotData(), heard::add)) {
                List<LoggedNode> watched = viewer.watch(List.of(new NodeSelection(POSTURE, "rad"),
                        new NodeSelection(SHIFT, "m")));
                int posture = watched.get(0).sourceId();
                int shift = watched.get(1).sourceId();
                assertThat(heard.await(e -> e.sourceId() == posture, 10_000)).as("posture values live").isTrue();
                assertThat(heard.await(e -> e.sourceId() == shift, 10_000)).as("Balance's values live").isTrue();

                // tau 1000 s: the shift (the body's offset towards the support triangle) stops following the gait
                ChangeOutcome slow = roq.setParameter(KEEP_BALANCE, "tau", "1000");
                assertThat(slow.executed()).as(slow.toString()).isTrue();
                assertThat(roq.snapshot().node(KEEP_BALANCE).parameter("tau")).isEqualTo("1000");
                heard.clear();
                Thread.sleep(2_500);
                List<double[]> after = heard.values(shift);
                assertThat(after).as("shift values after the change").hasSizeGreaterThan(10);
                assertThat(spread(after)).as("the shift barely moves with tau 1000 s").isLessThan(0.002);
                ChangeOutcome back = roq.setParameter(KEEP_BALANCE, "tau", "0.25");
                assertThat(back.executed()).as(back.toString()).isTrue();
                heard.clear();
                Thread.sleep(2_500);
                assertThat(spread(heard.values(shift))).as("with tau 0.25 s the shift follows the gait again")
                        .isGreaterThan(0.005);

                ChangeOutcome unload = roq.unload("Balance");
                assertThat(unload.executed()).as(unload.toString()).isTrue();
                Thread.sleep(300);
                heard.clear();
                assertThat(heard.await(e -> e.sourceId() == shift, 1_500)).as("no Balance values while unloaded")
                        .isFalse();
                assertThat(heard.await(e -> e.sourceId() == posture, 5_000)).as("posture still live").isTrue();
                ChangeOutcome load = roq.load("Balance");
                assertThat(load.executed()).as(load.toString()).isTrue();
                assertThat(heard.await(e -> e.sourceId() == shift, 10_000)).as("Balance's values flow again").isTrue();

                RunInfo run = viewer.runs().get(0);
                assertThat(printed).contains("run " + run.runId() + " ");
                PlotData replayed = new PlotData();
                Replay replay = ReplayLoader.load(viewer, run, -5, 0, 10, replayed).start();
                assertThat(replay.await(20_000)).as("the replay of the last 5 s finished").isTrue();
                assertThat(replay.total()).as("values in the run's last 5 s").isGreaterThan(50);
                assertThat(replay.delivered()).isEqualTo(replay.total());
            }
            assertThat(demo.awaitExit(45_000)).as(String.join("\n", demo.output())).isZero();
            assertThat(demo.output()).anyMatch(l -> l.startsWith("logger: ") && l.endsWith(", 0 lost"));
        }
    }

    /** Largest distance, over the shift's x and y, between two of its values. */
    private static double spread(List<double[]> values) {
        double spread = 0;
        for (int axis = 0; axis < 2; axis++) {
            double min = Double.POSITIVE_INFINITY;
            double max = Double.NEGATIVE_INFINITY;
            for (double[] v : values) {
                min = Math.min(min, v[axis]);
                max = Math.max(max, v[axis]);
            }
            spread = Math.max(spread, max - min);
        }
        return spread;
    }

    /** What the viewer client received, in order. */
    private static final class Heard {
        private final List<NetworkEvent> events = new ArrayList<>();

        synchronized void add(NetworkEvent e) {
            events.add(e);
            notifyAll();
        }

        synchronized void clear() {
            events.clear();
        }

        synchronized boolean await(Predicate<NetworkEvent> wanted, long millis) throws InterruptedException {
            long deadline = System.currentTimeMillis() + millis;
            while (events.stream().noneMatch(wanted)) {
                long left = deadline - System.currentTimeMillis();
                if (left <= 0) {
                    return false;
                }
                wait(left);
            }
            return true;
        }

        synchronized List<double[]> values(int source) {
            List<double[]> out = new ArrayList<>();
            for (NetworkEvent e : events) {
                if (e instanceof DataValueEvent d && d.sourceId() == source) {
                    String[] parts = d.value().text().replaceAll("[\\[\\]\\s]", "").split(",");
                    out.add(new double[] {Double.parseDouble(parts[0]), Double.parseDouble(parts[1])});
                }
            }
            return out;
        }
    }
}

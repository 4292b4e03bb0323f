package org.fdnet.roq.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.fdnet.control.LiveNetworkListener;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.corba.control.RemoteLiveNetwork;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Value;
import org.fdnet.testing.CliRun;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * {@code fdnet demo} publishes RoQ's network: attached through the control object, a balance parameter changes while
 * the robot walks, and the Balance module is unloaded (its value stops) and loaded again (it flows again).
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class DemoControlTest {
    private static final NodeRef KEEP_BALANCE = new NodeRef("Balance", "keep balance");
    private static final NodeRef BALANCE_SHIFT = new NodeRef("Balance", "balance shift");

    @Test
    void shouldLetAnAttachedToolChangeABalanceParameterAndUnloadAndReloadBalanceWhileRoqWalks() throws Exception {
        int port = FdnetChildProcess.freePort();
        CliRun cli = new CliRun();
        AtomicInteger exit = new AtomicInteger(-1);
        Thread demo = new Thread(() -> exit.set(cli.fdnet("demo", "--no-logger", "--for", "15s", "--network",
                RunOnSimulatorTest.WALK, "--control-port", Integer.toString(port))), "demo");
        demo.start();
        try (RemoteLiveNetwork roq = attach(port)) {
            BlockingQueue<Map<NodeRef, Value>> samples = new LinkedBlockingQueue<>();
            roq.subscribe(new LiveNetworkListener() {
                @Override
                public void changeSettled(ChangeOutcome outcome) {
                }

                @Override
                public void valuesSampled(Map<NodeRef, Value> latest) {
                    samples.add(latest);
                }

                @Override
                public void disconnected(String reason) {
                }
            });
            assertThat(sampled(samples, BALANCE_SHIFT, 10_000)).as("Balance's output sampled").isTrue();

            ChangeOutcome margin = roq.setParameter(KEEP_BALANCE, "margin", "0.08");
            assertThat(margin.executed()).as(margin.toString()).isTrue();
            assertThat(roq.snapshot().node(KEEP_BALANCE).parameter("margin")).isEqualTo("0.08");

            assertThat(roq.unload("Balance").executed()).isTrue();
            // A sample taken before the unload may still be on its way: start counting at the first one without it.
            assertThat(firstSampleWithout(samples, BALANCE_SHIFT, 10_000)).as("a sample after the unload").isTrue();
            samples.clear();
            assertThat(sampled(samples, BALANCE_SHIFT, 1_000)).as("no Balance values while it is unloaded").isFalse();
            assertThat(roq.load("Balance").executed()).isTrue();
            assertThat(sampled(samples, BALANCE_SHIFT, 10_000)).as("Balance's values flow again").isTrue();
        } finally {
            demo.join(60_000);
        }
        assertThat(exit.get()).as(cli.output()).isZero();
    }

    @Test
    void shouldRefuseToPublishTheControlObjectOnANonLoopbackAddressWithoutTls() {
        CliRun cli = new CliRun();
        java.io.ByteArrayOutputStream err = new java.io.ByteArrayOutputStream();
        java.io.PrintStream stderr = System.err;
        int exit;
        System.setErr(new java.io.PrintStream(err, true, java.nio.charset.StandardCharsets.UTF_8));
        try { // the demo writes its errors to System.err
            exit = cli.fdnet("demo", "--no-logger", "--for", "2s", "--network", RunOnSimulatorTest.WALK,
                    "--control-host", "192.0.2.1");
        } finally {
            System.setErr(stderr);
        }

        String said = err.toString(java.nio.charset.StandardCharsets.UTF_8);
        assertThat(exit).as(said).isEqualTo(2);
        assertThat(said).contains("fdnet demo: the network's control object would listen on 192.0.2.1")
                .contains("--tls").contains("--insecure");
        assertThat(cli.output()).doesNotContain("summary:");
    }

    /** The demo publishes once its simulator and network run: try for up to 30 s. */
    private static RemoteLiveNetwork attach(int port) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(30);
        while (true) {
            try {
                return RemoteLiveNetwork.attach("127.0.0.1:" + port, null);
            } catch (RuntimeException notYet) {
                if (System.nanoTime() > deadline) {
                    throw notYet;
                }
                Thread.sleep(200);
            }
        }
    }

    private static boolean firstSampleWithout(BlockingQueue<Map<NodeRef, Value>> samples, NodeRef data, long millis)
            throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        while (System.nanoTime() < deadline) {
            Map<NodeRef, Value> s = samples.poll(100, TimeUnit.MILLISECONDS);
            if (s != null && !s.containsKey(data)) {
                return true;
            }
        }
        return false;
    }

    private static boolean sampled(BlockingQueue<Map<NodeRef, Value>> samples, NodeRef data, long millis)
            throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        while (System.nanoTime() < deadline) {
            Map<NodeRef, Value> s = samples.poll(100, TimeUnit.MILLISECONDS);
            if (s != null && s.containsKey(data)) {
                return true;
            }
        }
        return false;
    }
}

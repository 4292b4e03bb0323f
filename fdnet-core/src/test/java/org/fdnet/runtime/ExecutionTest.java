package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.fdnet.runtime.TestNetworks.*;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class ExecutionTest {

    /** Records the most concurrent firings it saw of itself; sleeps a little to make overlaps likely. */
    public static class SlowCounter extends Relation {
        static final AtomicInteger running = new AtomicInteger();
        static final AtomicInteger maxSeen = new AtomicInteger();
        long count;

        @Override
        protected void compute(RelationContext c) throws Exception {
            int now = running.incrementAndGet();
            maxSeen.accumulateAndGet(now, Math::max);
            Thread.sleep(1);
            count++;
            c.outputAll(Value.of(count));
            running.decrementAndGet();
        }
    }

    @Test
    void shouldPropagateAValueThroughAChain() throws Exception {
        NetworkInfo n = new NetworkInfo("chain");
        n.addNode("main", data("In", "DoubleData"));
        n.addNode("main", data("Mid", "DoubleData"));
        n.addNode("main", data("Out", "DoubleData"));
        n.addNode("main", relation("Double", "Expression", "expression=2 * in0"));
        n.addNode("main", relation("Plus", "Expression", "expression=in0 + 1"));
        read(n, "main", "In", "Double");
        write(n, "main", "Double", "Mid");
        read(n, "main", "Mid", "Plus");
        write(n, "main", "Plus", "Out");
        try (RuntimeNetwork net = start(n, null)) {
            net.controller().setValue(ref("In"), "20");
            quiet(net);
            assertThat(net.controller().value(ref("Out")).asDouble()).isEqualTo(41.0);
        }
    }

    @Test
    void shouldNeverRunOneRelationConcurrentlyWithItselfAndNeverLoseTheLatestInput() throws Exception {
        NetworkInfo n = new NetworkInfo("concurrency");
        n.addNode("main", data("In", "DoubleData"));
        n.addNode("main", data("Count", "LongData"));
        n.addNode("main", data("Last", "DoubleData"));
        n.addNode("main", relation("Slow", SlowCounter.class.getName()));
        n.addNode("main", relation("Copy", "Expression", "expression=in0"));
        read(n, "main", "In", "Slow");
        write(n, "main", "Slow", "Count");
        read(n, "main", "In", "Copy");
        write(n, "main", "Copy", "Last");
        SlowCounter.maxSeen.set(0);
        try (RuntimeNetwork net = RuntimeNetwork.start(n, options().workerThreads(4).inlineCallers(false))) {
            Thread[] writers = new Thread[4];
            for (int w = 0; w < writers.length; w++) {
                int base = w * 1000;
                writers[w] = new Thread(() -> {
                    for (int i = 0; i < 200; i++) {
                        net.controller().setValue(ref("In"), Value.of((double) (base + i)));
                    }
                });
                writers[w].start();
            }
            for (Thread t : writers) {
                t.join();
            }
            net.controller().setValue(ref("In"), Value.of(-7.0));
            quiet(net);
            assertThat(SlowCounter.maxSeen.get()).isEqualTo(1);
            assertThat(net.controller().value(ref("Last")).asDouble()).isEqualTo(-7.0);
        }
    }

    /** Writes two outputs with the same number; a reader must never see them differ. */
    public static class Pair extends Relation {
        long k;

        @Override
        protected void compute(RelationContext c) {
            k++;
            c.output(0, Value.of(k));
            c.output(1, Value.of(k));
        }
    }

    /** Reads the pair and records any torn snapshot. */
    public static class PairChecker extends Relation {
        static final List<String> torn = new CopyOnWriteArrayList<>();

        @Override
        protected void compute(RelationContext c) {
            if (c.input(0).asLong() != c.input(1).asLong()) {
                torn.add(c.input(0) + " vs " + c.input(1));
            }
        }
    }

    @Test
    void shouldShowAFiringsOutputsTogether() throws Exception {
        NetworkInfo n = new NetworkInfo("atomic");
        n.addNode("main", data("A", "LongData"));
        n.addNode("main", data("B", "LongData"));
        n.addNode("main", data("Tick", "LongData"));
        n.addNode("main", relation("Pair", Pair.class.getName()));
        n.addNode("main", relation("Check", PairChecker.class.getName()));
        read(n, "main", "Tick", "Pair");
        write(n, "main", "Pair", "A");
        write(n, "main", "Pair", "B");
        read(n, "main", "A", "Check");
        read(n, "main", "B", "Check");
        PairChecker.torn.clear();
        try (RuntimeNetwork net = RuntimeNetwork.start(n, options().workerThreads(3).inlineCallers(false))) {
            for (int i = 0; i < 5000; i++) {
                net.controller().setValue(ref("Tick"), Value.of((long) i));
            }
            quiet(net);
            assertThat(PairChecker.torn).isEmpty();
            assertThat(net.controller().value(ref("A")).asLong()).isEqualTo(net.controller().value(ref("B")).asLong());
        }
    }

    @Test
    void shouldSettleAFeedbackLoopOnItsLatestValueWithoutLivelock() throws Exception {
        // the posture loop: Integrate reads Posture and writes it; a new Goal moves it halfway each firing
        NetworkInfo n = new NetworkInfo("loop");
        n.addNode("main", data("Goal", "DoubleData"));
        n.addNode("main", data("Posture", "DoubleData"));
        n.addNode("main", relation("Integrate", "Expression", "expression=Posture + 0.5 * (Goal - Posture)"));
        read(n, "main", "Goal", "Integrate");
        read(n, "main", "Posture", "Integrate");
        write(n, "main", "Integrate", "Posture");
        try (RuntimeNetwork net = start(n, null)) {
            quiet(net);
            long before = net.firings();
            net.controller().setValue(ref("Goal"), "8");
            quiet(net);
            // one firing per change of Goal: its own write does not re-trigger it
            assertThat(net.firings() - before).isEqualTo(1);
            assertThat(net.controller().value(ref("Posture")).asDouble()).isEqualTo(4.0);
            net.controller().setValue(ref("Goal"), "8");
            quiet(net);
            assertThat(net.controller().value(ref("Posture")).asDouble()).isEqualTo(6.0);
        }
    }

    @Test
    void shouldKeepAnEndlessTwoRelationLoopFromStarvingTheRestOfTheNetwork() throws Exception {
        NetworkInfo n = new NetworkInfo("ping-pong");
        n.addNode("main", data("Ping", "LongData"));
        n.addNode("main", data("Pong", "LongData"));
        n.addNode("main", data("Other", "DoubleData"));
        n.addNode("main", data("OtherOut", "DoubleData"));
        n.addNode("main", relation("A", "Expression", "expression=Pong + 1"));
        n.addNode("main", relation("B", "Expression", "expression=Ping + 1"));
        n.addNode("main", relation("C", "Expression", "expression=in0 * 10"));
        read(n, "main", "Pong", "A");
        write(n, "main", "A", "Ping");
        read(n, "main", "Ping", "B");
        write(n, "main", "B", "Pong");
        read(n, "main", "Other", "C");
        write(n, "main", "C", "OtherOut");
        try (RuntimeNetwork net = RuntimeNetwork.start(n, options().workerThreads(1))) {
            CountDownLatch seen = new CountDownLatch(1);
            net.controller().observe(ref("OtherOut"), (d, id, v) -> {
                if (v.asDouble() == 30.0) {
                    seen.countDown();
                }
            });
            Thread.sleep(50);
            net.controller().setValue(ref("Other"), "3");
            assertThat(seen.await(5, TimeUnit.SECONDS)).isTrue();
            assertThat(net.controller().value(ref("Ping")).asLong()).isGreaterThan(10);
        }
    }

    @Test
    void shouldFireAPeriodicRelationOnItsPeriod() throws Exception {
        NetworkInfo n = new NetworkInfo("periodic");
        n.addNode("main", data("Wave", "DoubleData"));
        n.addNode("main", relation("Source", "PeriodicSource", "period=10", "waveform=sawtooth"));
        write(n, "main", "Source", "Wave");
        try (RuntimeNetwork net = start(n, null)) {
            AtomicInteger values = new AtomicInteger();
            net.controller().observe(ref("Wave"), (d, id, v) -> values.incrementAndGet());
            Thread.sleep(300);
            assertThat(values.get()).isBetween(10, 40);
        }
    }

    @Test
    void shouldRefuseAnObserverThatWritesBackInsteadOfDeadlocking() throws Exception {
        NetworkInfo n = new NetworkInfo("reentrant");
        n.addNode("main", data("A", "DoubleData"));
        n.addNode("main", data("B", "DoubleData"));
        try (RuntimeNetwork net = start(n, null)) {
            List<Throwable> refused = new CopyOnWriteArrayList<>();
            net.controller().observe(ref("A"), (d, id, v) -> {
                try {
                    net.controller().setValue(ref("B"), v);
                } catch (IllegalStateException e) {
                    refused.add(e);
                }
            });
            net.controller().setValue(ref("A"), "1");
            assertThat(refused).singleElement().satisfies(e -> assertThat(e).hasMessageContaining("must enqueue and return"));
            net.controller().setValue(ref("B"), "2");
            assertThat(net.controller().value(ref("B")).asDouble()).isEqualTo(2.0);
        }
    }
}

package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.fdnet.runtime.TestNetworks.*;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * Many writers, feedback loops and module load/unload at once. Must end with no lost update (every value
 * of every Data reached its observer, in order; every Relation's output matches its last input) and no
 * deadlock (bounded by the timeout).
 */
class StressTest {
    private static final int WRITERS = 6;
    private static final int VALUES = 20_000;

    private static NetworkInfo network() {
        NetworkInfo n = new NetworkInfo("stress");
        for (int w = 0; w < WRITERS; w++) {
            n.addNode("main", data("In" + w, "LongData"));
            n.addNode("main", data("Out" + w, "LongData"));
            n.addNode("main", relation("Copy" + w, "Expression", "expression=in0"));
            read(n, "main", "In" + w, "Copy" + w);
            write(n, "main", "Copy" + w, "Out" + w);
            // a feedback loop per writer: Loop reads In and its own Acc and writes Acc
            n.addNode("main", data("Acc" + w, "DoubleData"));
            n.addNode("main", relation("Loop" + w, "Expression", "expression=0.5 * Acc" + w + " + 0.5 * In" + w));
            read(n, "main", "In" + w, "Loop" + w);
            read(n, "main", "Acc" + w, "Loop" + w);
            write(n, "main", "Loop" + w, "Acc" + w);
        }
        // a module that reads every writer's Data and is loaded and unloaded while they write
        n.addModule("Extra", true);
        n.addNode("Extra", data("Sum", "DoubleData"));
        n.addNode("Extra", relation("Adder", "Expression", "expression=" + sumOf()));
        for (int w = 0; w < WRITERS; w++) {
            read(n, "Extra", "In" + w, "Adder");
        }
        write(n, "Extra", "Adder", "Sum");
        return n;
    }

    private static String sumOf() {
        StringBuilder b = new StringBuilder("in0");
        for (int w = 1; w < WRITERS; w++) {
            b.append(" + in").append(w);
        }
        return b.toString();
    }

    @Test
    @Timeout(90)
    void shouldLoseNoUpdateAndNeverDeadlockUnderWritersLoopsAndModuleChurn() throws Exception {
        MemoryEventSink sink = new MemoryEventSink();
        RuntimeOptions options = options().workerThreads(4).sink(sink);
        try (RuntimeNetwork net = RuntimeNetwork.start(network(), options)) {
            Controller c = net.controller();
            ConcurrentHashMap<String, List<Long>> seen = new ConcurrentHashMap<>();
            for (int w = 0; w < WRITERS; w++) {
                String name = "In" + w;
                List<Long> values = java.util.Collections.synchronizedList(new ArrayList<>(VALUES));
                seen.put(name, values);
                c.observe(ref(name), (d, id, v) -> values.add(v.asLong()));
            }
            AtomicBoolean writing = new AtomicBoolean(true);
            AtomicLong churns = new AtomicLong();
            List<Throwable> errors = new CopyOnWriteArrayList<>();
            Thread churner = new Thread(() -> {
                try {
                    while (writing.get()) {
                        expect(c.unload("Extra"));
                        expect(c.load("Extra"));
                        expect(c.hold("Extra"));
                        expect(c.resume("Extra"));
                        churns.incrementAndGet();
                    }
                } catch (Throwable t) {
                    errors.add(t);
                }
            }, "churner");
            List<Thread> writers = new ArrayList<>();
            for (int w = 0; w < WRITERS; w++) {
                NodeRef in = ref("In" + w);
                boolean inline = w % 2 == 0;
                Thread t = new Thread(() -> {
                    try {
                        for (long i = 1; i <= VALUES; i++) {
                            c.setValue(in, Value.of(i));
                            if (!inline && i % 100 == 0) {
                                Thread.yield();
                            }
                        }
                    } catch (Throwable e) {
                        errors.add(e);
                    }
                }, "writer-" + w);
                writers.add(t);
            }
            churner.start();
            writers.forEach(Thread::start);
            for (Thread t : writers) {
                t.join();
            }
            writing.set(false);
            churner.join();
            quiet(net);
            assertThat(errors).isEmpty();
            assertThat(churns.get()).isPositive();
            for (int w = 0; w < WRITERS; w++) {
                List<Long> values = seen.get("In" + w);
                // every value, in order, exactly once
                assertThat(values).hasSize(VALUES);
                for (int i = 0; i < VALUES; i++) {
                    assertThat(values.get(i)).isEqualTo(i + 1L);
                }
                // the latest value made it through the Relation and the loop
                assertThat(c.value(ref("Out" + w)).asLong()).isEqualTo(VALUES);
                assertThat(c.relationState(ref("Loop" + w)).status()).isEqualTo(RelationStatus.RUNNING);
            }
            // the module came back after its last unload and caught up with the last values
            assertThat(c.loadedModules()).contains("Extra");
            assertThat(c.value(ref("Extra/Sum")).asDouble()).isEqualTo((double) VALUES * WRITERS);
            assertThat(c.relationStates()).noneMatch(s -> s.status() == RelationStatus.FAILED);
        }
    }

    private static void expect(ChangeOutcome o) {
        if (!o.executed()) {
            throw new AssertionError(o.toString());
        }
    }
}

package org.fdnet.roq.bridge;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.locks.LockSupport;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.roq.node.JointTargets;
import org.fdnet.roq.node.RoqSensor;
import org.fdnet.roq.sim.JointCommand;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.runtime.RuntimeNetwork;
import org.fdnet.runtime.Value;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Joins a running network to RoQ's simulator: each snapshot feeds the network's {@link RoqSensor} Datas, and
 * the value of its {@link JointTargets} Data goes to the simulator's command slot.
 *
 * <ul>
 *   <li><b>Stepped</b> ({@link #stepped}): the network runs on a {@link org.fdnet.runtime.DrivenClock} started at
 *   {@code startMicros}; {@link #run} alternates, on the caller's thread, {@code sim.step(cycleTicks)} →
 *   read the snapshot → feed the sensors → {@code network.advanceTo(start + tick ms)} → send the targets.
 *   Nothing else runs, so a run is reproducible.</li>
 *   <li><b>Real time</b> ({@link #realTime}): a thread of its own polls the loop's snapshot (a seqlock read,
 *   no JNI), feeds each new one and sends the targets; the simulator's 1 kHz loop never waits for it.</li>
 * </ul>
 * The sensors and targets are looked up by name on each cycle, so a module unloaded and loaded again is fed again.
 */
public final class SimBridge implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(SimBridge.class);

    private final RuntimeNetwork network;
    private final RoqSimulator simulator;
    private final List<NodeRef> sensors = new ArrayList<>();
    private final List<NodeRef> targets = new ArrayList<>();
    private final SensorSnapshot snapshot = new SensorSnapshot();
    private final JointCommand command = new JointCommand();
    private final long startMicros;
    private final int cycleTicks;
    private volatile boolean running;
    private Thread thread;
    private volatile long cycles;
    private volatile long lastTick = -1;

    private SimBridge(RuntimeNetwork network, RoqSimulator simulator, long startMicros, int cycleTicks) {
        this.network = network;
        this.simulator = simulator;
        this.startMicros = startMicros;
        this.cycleTicks = cycleTicks;
        network.readDefinition(def -> {
            for (ModuleInfo m : def.modules()) {
                for (NodeInfo n : m.nodes()) {
                    if (RoqSensor.class.getName().equals(n.className())) {
                        sensors.add(new NodeRef(m.name(), n.name()));
                    } else if (JointTargets.class.getName().equals(n.className())) {
                        targets.add(new NodeRef(m.name(), n.name()));
                    }
                }
            }
            return null;
        });
        if (targets.size() > 1) {
            throw new IllegalArgumentException("the network has " + targets.size() + " JointTargets Datas " + targets
                    + "; the simulator takes one set of targets");
        }
    }

    /**
     * A stepped bridge: {@code network} must run on a driven clock standing at {@code startMicros} and
     * {@code simulator} in STEPPED mode; each cycle is {@code cycleTicks} ticks (1 ms each).
     */
    public static SimBridge stepped(RuntimeNetwork network, RoqSimulator simulator, long startMicros, int cycleTicks) {
        if (cycleTicks < 1) {
            throw new IllegalArgumentException("cycleTicks must be at least 1, was " + cycleTicks);
        }
        return new SimBridge(network, simulator, startMicros, cycleTicks);
    }

    /** A real-time bridge on its own thread ("roq-bridge"); {@code network} runs on the wall clock. */
    public static SimBridge realTime(RuntimeNetwork network, RoqSimulator simulator) {
        SimBridge b = new SimBridge(network, simulator, 0, 1);
        b.running = true;
        b.thread = new Thread(b::poll, "roq-bridge");
        b.thread.setDaemon(true);
        b.thread.start();
        return b;
    }

    /** Stepped mode: runs {@code ticks} ticks of simulated time (rounded up to whole cycles) on this thread. */
    public void run(int ticks) {
        if (thread != null) {
            throw new IllegalStateException("run(ticks) is for a stepped bridge; this one runs in real time");
        }
        for (int done = 0; done < ticks; done += cycleTicks) {
            simulator.step(cycleTicks);
            long tick = simulator.read(snapshot);
            feed(tick);
            network.advanceTo(startMicros + tick * 1000L);
            sendTargets(tick);
            cycles++;
        }
    }

    private void poll() {
        while (running) {
            long tick = simulator.read(snapshot);
            if (tick == lastTick) {
                LockSupport.parkNanos(50_000);
                continue;
            }
            try {
                feed(tick);
                sendTargets(tick);
                cycles++;
            } catch (RuntimeException e) {
                LOG.error("roq-bridge: cycle at tick {} failed; the bridge goes on with the next snapshot", tick, e);
            }
        }
    }

    private void feed(long tick) {
        lastTick = tick;
        for (NodeRef ref : sensors) {
            RoqSensor s = network.dataInstance(ref, RoqSensor.class);
            if (s != null) {
                s.feed(snapshot, cycles);
            }
        }
    }

    private void sendTargets(long tick) {
        if (targets.isEmpty()) {
            return;
        }
        JointTargets t = network.dataInstance(targets.get(0), JointTargets.class);
        if (t == null) {
            return;
        }
        Value v = t.value();
        if (v == null || v.length() != RoqGeometry.JOINTS) {
            return;
        }
        for (int j = 0; j < RoqGeometry.JOINTS; j++) {
            command.target(j, v.element(j));
        }
        command.basedOnTick(tick);
        simulator.send(command);
    }

    /** The snapshot last fed (read it on the bridge's thread in stepped mode). */
    public SensorSnapshot lastSnapshot() {
        return snapshot;
    }

    /** Cycles run so far. */
    public long cycles() {
        return cycles;
    }

    /** Stops the real-time thread (a stepped bridge has none). Does not close the network or the simulator. */
    @Override
    public void close() {
        running = false;
        if (thread != null) {
            try {
                thread.join(2000);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
    }
}

package org.fdnet.roq.bridge;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.locks.LockSupport;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.roq.node.JointTargets;
import org.fdnet.roq.node.RoqSensor;
import org.fdnet.roq.sim.JointCommand;
import org.fdnet.roq.sim.RealTimeThreads;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.runtime.ChangeListener;
import org.fdnet.runtime.SensorData;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Joins a running network to RoQ's simulator: each snapshot feeds the network's {@link RoqSensor} Datas, all in
 * one commit and stamped with the snapshot's tick; each new value of its {@link JointTargets} Data goes to the
 * simulator's command slot as it is written.
 *
 * <pre>
 *   snapshot n ──read──▶ every RoqSensor's reading, tick n ──SensorData.pushTogether (one commit)──▶ network
 *   network ──JointTargets written (value observer)──▶ changed? ──▶ command, source tick = the value's ──▶ slot
 * </pre>
 *
 * <ul>
 *   <li><b>Stepped</b> ({@link #stepped}): the network runs on a {@link org.fdnet.runtime.engine.DrivenClock} started at
 *   {@code startMicros}; {@link #run} alternates, on the caller's thread, {@code sim.step(cycleTicks)} →
 *   read the snapshot → feed the sensors → {@code network.advanceTo(start + tick ms)}. Nothing else runs, so a
 *   run is reproducible.</li>
 *   <li><b>Real time</b> ({@link #realTime}): a thread of its own polls the loop's snapshot (a seqlock read,
 *   no JNI) and feeds each new one; the simulator's 1 kHz loop never waits for it. The thread runs under
 *   SCHED_FIFO just below the loop when the system allows ({@link RealTimeThreads}): the network's event-driven
 *   Relations fire on it, and on a loaded machine an ordinary thread waited up to 2.5 ms for its core. Give the
 *   network's workers the same with {@code RuntimeOptions.workerStart(RealTimeThreads::promoteCurrentThread)}.</li>
 * </ul>
 *
 * <p>Commands are observed, not polled. In real time every value JointTargets takes that differs from the last one
 * sent is sent at once (from the commit that wrote it), so none is skipped and none waits for the next snapshot.
 * Stepped, the newest value of each cycle is sent at the cycle's end (the loop takes one command a tick, and a
 * firing that finishes on a worker thread after {@code advanceTo} must not reach the loop at a wall-clock moment:
 * the run stays reproducible). Its source tick
 * ({@link Value#tick()}, the newest snapshot it was computed from) goes with it ({@link JointCommand#sourceTick});
 * its freshness for the loop's staleness check is the newest snapshot read.
 *
 * <p>The bridge follows the network: after every settled change (edit, load, unload, reload, parameter change) it
 * looks again for RoqSensor and JointTargets nodes, so one added or loaded is fed or followed from the next
 * snapshot on, and one removed or unloaded is dropped at once.
 */
public final class SimBridge implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(SimBridge.class);

    private final RuntimeNetwork network;
    private final RoqSimulator simulator;
    private final SensorSnapshot snapshot = new SensorSnapshot();
    private final JointCommand command = new JointCommand();
    private final long startMicros;
    private final int cycleTicks;
    private final ChangeListener follower = outcome -> follow();
    /** Guarded by this: the JointTargets followed, by name, and their observer handles. */
    private final Map<NodeRef, AutoCloseable> targetObservers = new HashMap<>();
    private volatile RoqSensor[] sensors = new RoqSensor[0];
    /** The feeding thread's scratch for one commit. */
    private SensorData[] pushSensors = new SensorData[0];
    private Value[] pushValues = new Value[0];
    /** Guarded by {@link #command}: the last value sent, and (stepped) the newest one waiting for the cycle's end. */
    private Value lastSent;
    private Value pending;
    private final boolean realTime;
    private volatile boolean running;
    private Thread thread;
    private volatile long cycles;
    private volatile long commandsSent;
    /** Real time: the longest wall-clock time from one snapshot's feed to the next's, ns (0 before two feeds). */
    private volatile long longestFeedGapNanos;
    /** The loop's tick of the snapshot that ended the longest gap (-1 before two feeds). */
    private volatile long longestFeedGapTick = -1;

    private SimBridge(RuntimeNetwork network, RoqSimulator simulator, long startMicros, int cycleTicks,
                      boolean realTime) {
        this.network = network;
        this.realTime = realTime;
        this.simulator = simulator;
        this.startMicros = startMicros;
        this.cycleTicks = cycleTicks;
        List<NodeRef> targets = nodesOf(JointTargets.class);
        if (targets.size() > 1) {
            throw new IllegalArgumentException("the network has " + targets.size() + " JointTargets Datas " + targets
                    + "; the simulator takes one set of targets");
        }
        network.controller().addChangeListener(follower);
        follow();
    }

    /**
     * A stepped bridge: {@code network} must run on a driven clock standing at {@code startMicros} and
     * {@code simulator} in STEPPED mode; each cycle is {@code cycleTicks} ticks (1 ms each).
     */
    public static SimBridge stepped(RuntimeNetwork network, RoqSimulator simulator, long startMicros, int cycleTicks) {
        if (cycleTicks < 1) {
            throw new IllegalArgumentException("cycleTicks must be at least 1, was " + cycleTicks);
        }
        return new SimBridge(network, simulator, startMicros, cycleTicks, false);
    }

    /** A real-time bridge on its own thread ("roq-bridge"); {@code network} runs on the wall clock. */
    public static SimBridge realTime(RuntimeNetwork network, RoqSimulator simulator) {
        SimBridge b = new SimBridge(network, simulator, 0, 1, true);
        b.running = true;
        b.thread = new Thread(b::poll, "roq-bridge");
        b.thread.setDaemon(true);
        b.thread.start();
        return b;
    }

    /** Stepped mode: runs {@code ticks} ticks of simulated time (rounded up to whole cycles) on this thread. */
    public void run(int ticks) {
        if (realTime) {
            throw new IllegalStateException("run(ticks) is for a stepped bridge; this one runs in real time");
        }
        for (int done = 0; done < ticks; done += cycleTicks) {
            simulator.step(cycleTicks);
            long tick = simulator.read(snapshot);
            feed();
            network.advanceTo(startMicros + tick * 1000L);
            sendPending();
            cycles++;
        }
    }

    private void poll() {
        RealTimeThreads.promoteCurrentThread();
        long lastTick = -1;
        long lastFeed = 0;
        while (running) {
            long tick = simulator.read(snapshot);
            if (tick == lastTick) {
                LockSupport.parkNanos(50_000);
                continue;
            }
            lastTick = tick;
            long now = System.nanoTime();
            if (lastFeed != 0 && now - lastFeed > longestFeedGapNanos) {
                longestFeedGapNanos = now - lastFeed;
                longestFeedGapTick = tick;
            }
            lastFeed = now;
            try {
                feed();
                cycles++;
            } catch (RuntimeException e) {
                LOG.error("roq-bridge: cycle at tick {} failed; the bridge goes on with the next snapshot", tick, e);
            }
        }
    }

    /** Pushes every running RoqSensor's reading of the snapshot in one commit. */
    private void feed() {
        RoqSensor[] now = sensors;
        if (pushSensors.length != now.length) {
            pushSensors = new SensorData[now.length];
            pushValues = new Value[now.length];
        }
        for (int i = 0; i < now.length; i++) {
            pushSensors[i] = now[i];
            pushValues[i] = now[i].reading(snapshot, cycles);
        }
        SensorData.pushTogether(pushSensors, pushValues);
    }

    /** A JointTargets value (called under the network's commit lock: sends and returns, never blocks). */
    private void targetsWritten(NodeRef ref, int id, Value v) {
        if (v == null || v.length() != RoqGeometry.JOINTS) {
            return;
        }
        synchronized (command) {
            if (realTime) {
                send(v);
            } else {
                pending = v; // stepped: the loop takes one command a tick; send at the cycle's end, reproducibly
            }
        }
    }

    private void sendPending() {
        synchronized (command) {
            if (pending != null) {
                send(pending);
                pending = null;
            }
        }
    }

    /** Sends {@code v} unless it equals the last value sent (the caller holds {@link #command}). */
    private void send(Value v) {
        if (v.samePayload(lastSent)) {
            return;
        }
        lastSent = v;
        for (int j = 0; j < RoqGeometry.JOINTS; j++) {
            command.target(j, v.element(j));
        }
        command.basedOnTick(-1).sourceTick(v.tick());
        simulator.send(command);
        commandsSent++;
    }

    /** Looks again for the network's RoqSensor and JointTargets nodes. */
    private synchronized void follow() {
        List<RoqSensor> running = new ArrayList<>();
        for (NodeRef ref : nodesOf(RoqSensor.class)) {
            RoqSensor s = network.dataInstance(ref, RoqSensor.class);
            if (s != null) {
                running.add(s);
            }
        }
        sensors = running.toArray(new RoqSensor[0]);
        List<NodeRef> targets = nodesOf(JointTargets.class);
        targetObservers.entrySet().removeIf(e -> {
            if (targets.contains(e.getKey())) {
                return false;
            }
            closeQuietly(e.getValue());
            return true;
        });
        for (NodeRef ref : targets) {
            if (!targetObservers.containsKey(ref)) {
                targetObservers.put(ref, network.controller().observe(ref, this::targetsWritten));
                JointTargets t = network.dataInstance(ref, JointTargets.class);
                if (t != null) {
                    targetsWritten(ref, -1, t.value());
                }
            }
        }
        if (targets.size() > 1) {
            LOG.warn("roq-bridge: the network now has {} JointTargets Datas {}; each value written to any is sent",
                    targets.size(), targets);
        }
    }

    private List<NodeRef> nodesOf(Class<?> type) {
        return network.readDefinition(def -> nodesOf(def, type));
    }

    /** The nodes of {@code definition} whose class is {@code type} (by name), in definition order. */
    public static List<NodeRef> nodesOf(NetworkInfo definition, Class<?> type) {
        List<NodeRef> refs = new ArrayList<>();
        for (ModuleInfo m : definition.modules()) {
            for (NodeInfo n : m.nodes()) {
                if (type.getName().equals(n.className())) {
                    refs.add(new NodeRef(m.name(), n.name()));
                }
            }
        }
        return refs;
    }

    private static void closeQuietly(AutoCloseable handle) {
        try {
            handle.close();
        } catch (Exception e) {
            LOG.warn("roq-bridge: closing a JointTargets observer failed", e);
        }
    }

    /** The snapshot last fed (read it on the bridge's thread in stepped mode). */
    public SensorSnapshot lastSnapshot() {
        return snapshot;
    }

    /** Cycles run so far. */
    public long cycles() {
        return cycles;
    }

    /**
     * Real time: the longest wall-clock time between feeding two snapshots to the network, ns. The loop publishes a
     * snapshot each millisecond, so this is about 1 ms unless the bridge's thread was held: by a commit blocked in the
     * network (for instance by an event sink that waits for the logger) or by the machine's scheduler. 0 in stepped
     * mode and before two feeds.
     */
    public long longestFeedGapNanos() {
        return longestFeedGapNanos;
    }

    /** The loop's tick (1 ms each from its start) of the snapshot fed after the longest gap; -1 before two feeds. */
    public long longestFeedGapTick() {
        return longestFeedGapTick;
    }

    /** Commands sent so far: one per JointTargets value that differed from the one before. */
    public long commandsSent() {
        return commandsSent;
    }

    /** The RoqSensor Datas fed now. */
    public int sensorsFed() {
        return sensors.length;
    }

    /** Stops the real-time thread (a stepped bridge has none) and stops following the network. */
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
        network.controller().removeChangeListener(follower);
        synchronized (this) {
            targetObservers.values().forEach(SimBridge::closeQuietly);
            targetObservers.clear();
        }
    }
}

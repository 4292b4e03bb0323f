package org.fdnet.control;

import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.function.Consumer;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeListener;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Value;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One subscriber of a {@link LiveNetwork} in this process: its own thread tells it, in order, every settled change and,
 * ten times a second, the Datas written since the previous sample. A listener that throws is logged and kept;
 * closing the handle stops the thread and the change listener.
 */
public final class LiveSubscription implements AutoCloseable, ChangeListener {
    private static final Logger LOG = LoggerFactory.getLogger(LiveSubscription.class);
    static final long SAMPLE_MILLIS = 100;

    private final SampledNetwork network;
    private final LiveNetworkListener listener;
    private final Consumer<LiveSubscription> onClose;
    private final ScheduledExecutorService thread;
    private final Map<NodeRef, Value> lastSeen = new HashMap<>();
    private volatile boolean structureChanged = true;
    private List<NodeRef> datas = List.of();

    /** A subscription of {@code listener} to {@code network}; {@code onClose} is told when it ends. Call {@link #start()}. */
    public LiveSubscription(String networkName, SampledNetwork network, LiveNetworkListener listener,
                            Consumer<LiveSubscription> onClose) {
        this.network = network;
        this.listener = listener;
        this.onClose = onClose;
        this.thread = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "fdnet-live-" + networkName);
            t.setDaemon(true);
            return t;
        });
    }

    public void start() {
        network.addChangeListener(this);
        thread.scheduleAtFixedRate(this::sample, 0, SAMPLE_MILLIS, TimeUnit.MILLISECONDS);
    }

    @Override
    public void changeSettled(ChangeOutcome outcome) {
        structureChanged = true;
        run(() -> listener.changeSettled(outcome), "changeSettled");
    }

    private void sample() {
        if (structureChanged) {
            structureChanged = false;
            datas = network.runningDatas();
            lastSeen.keySet().retainAll(datas);
        }
        Map<NodeRef, Value> latest = new LinkedHashMap<>();
        for (NodeRef d : datas) {
            Value v = network.value(d);
            if (v != null && lastSeen.get(d) != v) {
                lastSeen.put(d, v);
                latest.put(d, v);
            }
        }
        if (!latest.isEmpty()) {
            call(() -> listener.valuesSampled(latest), "valuesSampled");
        }
    }

    /** The network stopped: the listener's last call, then the subscription ends. */
    public void disconnect(String reason) {
        network.removeChangeListener(this);
        run(() -> listener.disconnected(reason), "disconnected");
        close();
    }

    private void run(Runnable call, String what) {
        try {
            thread.execute(() -> call(call, what));
        } catch (RejectedExecutionException closed) {
            LOG.debug("subscription closed; {} not delivered", what);
        }
    }

    private void call(Runnable call, String what) {
        try {
            call.run();
        } catch (RuntimeException e) {
            LOG.warn("a live network listener failed in {}: {}", what, e.toString(), e);
        }
    }

    @Override
    public void close() {
        network.removeChangeListener(this);
        thread.shutdown();
        onClose.accept(this);
    }
}

package org.fdnet.runtime.engine;

import java.util.List;
import java.util.concurrent.ScheduledFuture;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.NodeLifecycle;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationState;
import org.fdnet.runtime.RelationStatus;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The engine's side of a Relation instance. Its {@link #state} is what keeps one Relation from running
 * twice at once while never losing a request to run:
 *
 * <pre>
 *   IDLE ──input/period──▶ QUEUED ──worker──▶ RUNNING ──done──▶ IDLE
 *                                              │   ▲
 *                               input meanwhile▼   │ done: run again (sees the latest inputs)
 *                                            AGAIN ┘
 * </pre>
 *
 * Requests while QUEUED or AGAIN coalesce: the next firing reads the latest values anyway.
 */
final class RelationNode {
    private static final Logger LOG = LoggerFactory.getLogger(RelationNode.class);
    static final int IDLE = 0;
    static final int QUEUED = 1;
    static final int RUNNING = 2;
    static final int AGAIN = 3;

    final int id;
    final NodeRef ref;
    final NodeInfo info;
    final Relation relation;
    /** 0 when the Relation has no period. */
    final long periodMillis;
    /** Whether a change of an input makes it fire (else only its period does). */
    final boolean fireOnInput;
    /** The inputs whose changes make it fire (node names or Module/Node), or {@code null} for all. */
    final java.util.Set<String> triggers;
    final AtomicInteger state = new AtomicInteger(IDLE);
    final AtomicBoolean periodDue = new AtomicBoolean();
    private final FiringContext context;

    volatile Wiring wiring = Wiring.EMPTY;
    volatile boolean alive = true;
    volatile boolean held;
    volatile boolean missedWhileHeld;
    volatile RelationStatus status = RelationStatus.RUNNING;
    volatile Throwable failure;
    volatile List<NodeRef> missing = List.of();
    volatile long firings;
    ScheduledFuture<?> periodic;
    /** On a driven clock: when the period next falls due, µs (0 when it has none). */
    long nextDueMicros;
    /** The state text last reported as an event (structure lock). */
    String reportedState;

    RelationNode(int id, NodeRef ref, NodeInfo info, Relation relation, long periodMillis, boolean fireOnInput,
                 java.util.Set<String> triggers, Dataflow flow) {
        this.triggers = triggers;
        this.id = id;
        this.ref = ref;
        this.info = info;
        this.relation = relation;
        this.periodMillis = periodMillis;
        this.fireOnInput = fireOnInput;
        this.context = new FiringContext(this, flow);
    }

    /** A request to run: true when the caller must dispatch this node (it went IDLE → QUEUED). */
    boolean request() {
        while (true) {
            int s = state.get();
            if (s == IDLE) {
                if (state.compareAndSet(IDLE, QUEUED)) {
                    return true;
                }
            } else if (s == RUNNING) {
                if (state.compareAndSet(RUNNING, AGAIN)) {
                    return false;
                }
            } else {
                return false;
            }
        }
    }

    /** Runs one firing, then settles: back to IDLE, or — if asked again meanwhile — queued once more. */
    void runAndSettle(Dataflow flow) {
        state.set(RUNNING);
        try {
            fire(flow);
        } finally {
            if (state.compareAndSet(RUNNING, IDLE)) {
                flow.settled();
            } else {
                state.set(QUEUED);
                flow.scheduler().dispatch(this);
            }
        }
    }

    private void fire(Dataflow flow) {
        if (!alive || status == RelationStatus.FAILED) {
            return;
        }
        if (held) {
            missedWhileHeld = true;
            return;
        }
        boolean periodicNow = periodDue.getAndSet(false);
        Wiring w = wiring;
        try {
            context.begin(w, periodicNow);
            NodeLifecycle.compute(relation, context);
            context.commit(w);
            firings++;
            flow.countFiring();
        } catch (Throwable t) {
            if (t instanceof VirtualMachineError && !(t instanceof StackOverflowError)) {
                throw (VirtualMachineError) t;
            }
            context.discard();
            fail(flow, t);
        }
    }

    void fail(Dataflow flow, Throwable cause) {
        failure = cause;
        status = RelationStatus.FAILED;
        LOG.warn("{} FAILED; the rest of the network runs on", ref, cause);
        flow.reportState(this);
        try {
            NodeLifecycle.close(relation);
        } catch (RuntimeException e) {
            LOG.warn("{}: close after failure failed", ref, e);
        }
    }

    /** Whether a new value of {@code data} makes this Relation fire. */
    boolean triggeredBy(NodeRef data) {
        return fireOnInput && (triggers == null || triggers.contains(data.node()) || triggers.contains(data.toString()));
    }

    RelationState state() {
        return new RelationState(ref, status, failure, missing, firings);
    }

    FiringContext context() {
        return context;
    }

    @Override
    public String toString() {
        return ref + "#" + id;
    }
}

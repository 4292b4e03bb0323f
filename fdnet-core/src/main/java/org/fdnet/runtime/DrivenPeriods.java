package org.fdnet.runtime;

import java.util.PriorityQueue;

/**
 * The period timer of a network on a {@link DrivenClock}: Relations' periods fall due in simulated time and
 * fire when the driver advances the clock past them, earliest first, ties in node-id order — never on a
 * thread of their own. A Relation that leaves the network is dropped the next time its turn comes.
 */
final class DrivenPeriods {
    private record Due(long simMicros, int nodeId, RelationNode node) {
    }

    private final PriorityQueue<Due> queue = new PriorityQueue<>((a, b) -> a.simMicros != b.simMicros
            ? Long.compare(a.simMicros, b.simMicros) : Integer.compare(a.nodeId, b.nodeId));
    private final DrivenClock clock;

    DrivenPeriods(DrivenClock clock) {
        this.clock = clock;
    }

    /** The node's first period falls due one period after now. */
    synchronized void start(RelationNode node) {
        queue.add(new Due(clock.simMicros() + node.periodMillis * 1000, node.id, node));
    }

    /**
     * Takes the earliest period due at or before {@code untilSim}, moves the clock to it and schedules the next;
     * returns the node to fire, or {@code null} when nothing more is due by then.
     */
    synchronized RelationNode nextDue(long untilSim) {
        while (!queue.isEmpty() && queue.peek().simMicros <= untilSim) {
            Due due = queue.poll();
            if (!due.node.alive) {
                continue;
            }
            clock.moveTo(Math.max(due.simMicros, clock.simMicros()));
            queue.add(new Due(due.simMicros + due.node.periodMillis * 1000, due.nodeId, due.node));
            return due.node;
        }
        return null;
    }
}

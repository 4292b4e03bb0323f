package org.fdnet.corba;

import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.ArrayBlockingQueue;
import java.util.concurrent.atomic.AtomicLong;
import java.util.function.Predicate;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkEvent;
import org.fdnet.netinfo.NodeRef;

/**
 * A host's own events of one run, kept for {@code --trace} until the run's process takes them ({@code takeTrace}).
 *
 * <pre>
 *   engine thread ─accept─▶ [ring of capacity events] ─take(max), on an ORB thread─▶ lines with node names
 *                   full? drop and count ───────────────▶ "dropped" in the next batch
 * </pre>
 *
 * The engine never waits and memory stays bounded however slowly the trace is read: an event that finds the ring
 * full is dropped and counted, and the next batch says how many. Stand-ins' events are left out
 * ({@link StandInEvents}); the text is made when taken, off the engine's threads.
 */
final class HostTrace implements EventSink {
    /** Longest text of one line: a large value (bytes, a long array) is cut here so a batch stays small. */
    static final int MAX_LINE_CHARS = 1_000;

    private final UUID run;
    private final ArrayBlockingQueue<NetworkEvent> kept;
    private final AtomicLong dropped = new AtomicLong();
    private final StandInEvents standIns;
    private final TraceText text = new TraceText();

    /** One event as the run's process prints it. */
    record Line(long timeMicros, String text) {
    }

    /** What one take returns: lines, oldest first, and the events dropped since the take before. */
    record Batch(List<Line> lines, long dropped) {
        static final Batch EMPTY = new Batch(List.of(), 0);
    }

    HostTrace(UUID run, int capacity, Predicate<NodeRef> standIn) {
        this.run = run;
        this.kept = new ArrayBlockingQueue<>(capacity);
        this.standIns = new StandInEvents(standIn);
    }

    UUID run() {
        return run;
    }

    @Override
    public void accept(NetworkEvent event) {
        if (standIns.test(event)) {
            return;
        }
        text.learn(event); // names stay known even when the naming event itself is dropped
        if (!kept.offer(event)) {
            dropped.incrementAndGet();
        }
    }

    /** Up to {@code max} kept events as lines, oldest first; one taker at a time. */
    synchronized Batch take(int max) {
        List<NetworkEvent> events = new ArrayList<>(Math.min(max, kept.size()));
        kept.drainTo(events, max);
        List<Line> lines = new ArrayList<>(events.size());
        for (NetworkEvent e : events) {
            String t = text.of(e);
            lines.add(new Line(e.time(), t.length() > MAX_LINE_CHARS ? t.substring(0, MAX_LINE_CHARS - 3) + "..." : t));
        }
        return new Batch(lines, dropped.getAndSet(0));
    }
}

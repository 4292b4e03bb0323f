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
 *   engine thread ─accept─▶ line (names, cut at MAX_LINE_CHARS) ─▶ [ring of capacity lines] ─take(max)─▶ batch
 *                                          full? drop and count ─────────────────────────▶ "dropped" in the next batch
 * </pre>
 *
 * The engine never waits and memory stays bounded however slowly the trace is read: a line that finds the ring full
 * is dropped and counted, and the next batch says how many; a kept line is at most {@link #MAX_LINE_CHARS} long, so
 * the ring holds at most capacity × that many characters whatever the values (an event keeps its whole value, which
 * may be large: it is not kept). Stand-ins' events are left out ({@link StandInEvents}).
 */
final class HostTrace implements EventSink {
    /** Longest text of one line: a large value (bytes, a long array) is cut here so a batch stays small. */
    static final int MAX_LINE_CHARS = 1_000;

    private final UUID run;
    private final ArrayBlockingQueue<Line> kept;
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
        if (kept.remainingCapacity() == 0) { // spare the text of a line that cannot be kept
            text.learn(event); // names stay known even when the naming event itself is dropped
            dropped.incrementAndGet();
            return;
        }
        String t = text.of(event);
        if (!kept.offer(new Line(event.time(), t.length() > MAX_LINE_CHARS
                ? t.substring(0, MAX_LINE_CHARS - 3) + "..." : t))) {
            dropped.incrementAndGet();
        }
    }

    /** Up to {@code max} kept lines, oldest first; one taker at a time. */
    synchronized Batch take(int max) {
        List<Line> lines = new ArrayList<>(Math.min(max, kept.size()));
        kept.drainTo(lines, max);
        return new Batch(lines, dropped.getAndSet(0));
    }
}

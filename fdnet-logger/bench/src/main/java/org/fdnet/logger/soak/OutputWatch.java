package org.fdnet.logger.soak;

import java.util.ArrayList;
import java.util.IdentityHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.Predicate;
import org.fdnet.corba.FdnetChildProcess;

/**
 * Reads what the soak's processes print, as they print it, and keeps each line with the time it was first seen (every
 * {@value #PERIOD_MILLIS} ms): when the run said a host was lost or back, when a host's health line said its logger
 * was away. A process started again is a new output, read from its start.
 */
final class OutputWatch implements Runnable {
    private static final long PERIOD_MILLIS = 20;

    /** One line of process {@code process}, first seen at {@code atMillis} (epoch). */
    record Line(String process, long atMillis, String text) {
    }

    private final SoakCluster cluster;
    private final Map<FdnetChildProcess, Integer> read = new IdentityHashMap<>();
    private final List<Line> lines = new ArrayList<>();
    private volatile boolean stopping;

    OutputWatch(SoakCluster cluster) {
        this.cluster = cluster;
    }

    @Override
    public void run() {
        while (!stopping) {
            poll();
            try {
                Thread.sleep(PERIOD_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    private void poll() {
        long now = System.currentTimeMillis();
        for (String name : cluster.names()) {
            FdnetChildProcess p = cluster.process(name);
            List<String> out = p.output();
            int from = read.getOrDefault(p, 0);
            if (out.size() > from) {
                synchronized (this) {
                    for (String text : out.subList(from, out.size())) {
                        lines.add(new Line(name, now, text));
                    }
                }
                read.put(p, out.size());
            }
        }
    }

    void stop() {
        stopping = true;
    }

    /** The lines seen from {@code fromMillis} to {@code toMillis} that {@code wanted} accepts, in order. */
    synchronized List<Line> between(long fromMillis, long toMillis, Predicate<Line> wanted) {
        List<Line> found = new ArrayList<>();
        for (Line l : lines) {
            if (l.atMillis() >= fromMillis && l.atMillis() <= toMillis && wanted.test(l)) {
                found.add(l);
            }
        }
        return found;
    }
}

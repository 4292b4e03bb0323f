package org.fdnet.corba;

import java.util.Locale;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;
import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.TraceBatch;
import org.fdnet.corba.idl.TraceLine;
import org.omg.CORBA.SystemException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A distributed run's {@code --trace}: drains every host's trace of the run ({@code takeTrace}) and hands each line,
 * named by its host, to a {@link TraceOutput}.
 *
 * <pre>
 *   host flyer   [HostTrace: ≤ capacity events] ◀─takeTrace(run, BATCH)─┐
 *   host crawler [HostTrace]                    ◀─takeTrace─────────────┼─ one thread here, every PERIOD_MILLIS
 *   this host    [HostTrace]                    ◀─takeTrace─────────────┘   ─▶ TraceOutput (lines, drops)
 * </pre>
 *
 * Pulled, never pushed: each host keeps at most its capacity and drops (and counts) what does not fit, so a slow
 * reader here costs lines, never a host's progress or memory. A host is drained until it has nothing left or
 * {@link #ROUNDS_PER_HOST} batches were taken, so one busy host does not starve the others' lines. A lost host is
 * skipped; told the run again when it comes back, it traces again.
 */
public final class TraceCollector implements AutoCloseable {
    /** Lines a host keeps for the trace at most (each at most {@link HostTrace#MAX_LINE_CHARS} characters). */
    public static final int HOST_CAPACITY = 10_000;
    static final int BATCH = 500;
    static final int ROUNDS_PER_HOST = 8;
    static final long PERIOD_MILLIS = 100;
    private static final Logger LOG = LoggerFactory.getLogger(TraceCollector.class);

    private final NetworkDeployment deployment;
    private final String run;
    private final TraceOutput output;
    private final Map<String, LongAdder> lines = new ConcurrentHashMap<>();
    private final Map<String, LongAdder> dropped = new ConcurrentHashMap<>();
    private final Thread thread;
    private volatile boolean closed;

    private TraceCollector(NetworkDeployment deployment, String run, TraceOutput output) {
        this.deployment = deployment;
        this.run = run;
        this.output = output;
        this.thread = new Thread(this::collect, "fdnet-trace");
        this.thread.setDaemon(true);
    }

    /** Starts draining the hosts of {@code deployment}, which were told to trace its run. */
    public static TraceCollector start(NetworkDeployment deployment, TraceOutput output) {
        RunRecording recording = deployment.recording().filter(RunRecording::traced).orElseThrow(
                () -> new IllegalArgumentException("the deployment's hosts were not told to trace its run"));
        TraceCollector c = new TraceCollector(deployment, recording.run().id().toString(), output);
        c.thread.start();
        return c;
    }

    private void collect() {
        while (!closed) {
            drainAll();
            try {
                Thread.sleep(PERIOD_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    private synchronized void drainAll() {
        for (String name : deployment.plan().hosts()) {
            Host host = deployment.host(name);
            if (host == null || deployment.lostHosts().contains(name)) {
                continue;
            }
            try {
                drain(name, host);
            } catch (SystemException e) {
                LOG.debug("trace of host {} not read now: {}", name, e.toString()); // the watcher reports the host
            }
        }
    }

    private void drain(String name, Host host) {
        long offset = deployment.clockOffsetMicros(name);
        for (int round = 0; round < ROUNDS_PER_HOST; round++) {
            TraceBatch batch = host.takeTrace(run, BATCH);
            if (batch.dropped > 0) {
                dropped.computeIfAbsent(name, h -> new LongAdder()).add(batch.dropped);
                output.dropped(name, batch.dropped);
            }
            for (TraceLine line : batch.lines) {
                output.line(name, line.timeMicros - offset, line.text);
            }
            lines.computeIfAbsent(name, h -> new LongAdder()).add(batch.lines.length);
            if (batch.lines.length < BATCH) {
                return;
            }
        }
    }

    /** Lines shown and events dropped, by host, so far: {@code flyer 1,234 lines (0 dropped)}. */
    public String tally() {
        StringBuilder b = new StringBuilder();
        for (String name : deployment.plan().hosts()) {
            b.append(b.length() == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%s %,d lines (%,d dropped)",
                    name, count(lines, name), count(dropped, name)));
        }
        return b.toString();
    }

    /** Events of {@code host} dropped so far because its buffer was full. */
    public long droppedOn(String host) {
        return count(dropped, host);
    }

    private static long count(Map<String, LongAdder> counts, String host) {
        LongAdder a = counts.get(host);
        return a == null ? 0 : a.sum();
    }

    /** Stops draining after one last round (what the hosts still keep is shown) and ends every host's trace. */
    @Override
    public void close() {
        if (closed) {
            return;
        }
        closed = true; // not interrupted: an ORB call cut short would lose the batch it carried
        try {
            thread.join(5_000);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        drainAll();
        for (String name : deployment.plan().hosts()) {
            Host host = deployment.host(name);
            if (host != null && !deployment.lostHosts().contains(name)) {
                try {
                    host.endTrace(run);
                } catch (SystemException e) {
                    LOG.debug("host {} did not end its trace: {}", name, e.toString());
                }
            }
        }
    }
}

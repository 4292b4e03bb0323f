package org.fdnet.run;

import java.io.PrintWriter;
import java.util.Locale;
import org.fdnet.corba.TraceOutput;
import org.fdnet.corba.TraceText;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkEvent;

/**
 * {@code fdnet run --trace}: prints every event as it happens, with node names instead of ids. On one host it is a
 * sink of the engine; in a distributed run it prints the lines every host's trace hands over ({@link TraceOutput}),
 * each naming its host, and the deployment's host and link events as this process's host's.
 */
final class TracePrinter implements EventSink, TraceOutput {
    private final PrintWriter out;
    private final TraceText text = new TraceText();
    private final long start;
    private final String host;

    /** {@code host}: the name this process's own events are printed under; {@code null} on one host (no names). */
    TracePrinter(PrintWriter out, long startMicros, String host) {
        this.out = out;
        this.start = startMicros;
        this.host = host;
    }

    @Override
    public void accept(NetworkEvent event) {
        print(host, event.time(), text.of(event));
    }

    @Override
    public void line(String host, long timeMicros, String line) {
        print(host, timeMicros, line);
    }

    @Override
    public void dropped(String host, long count) {
        synchronized (out) {
            out.printf(Locale.ROOT, "trace: %,d trace lines dropped on host %s (its trace buffer was full: this"
                    + " process read it too slowly; the logger keeps every event)%n", count, host);
        }
    }

    private void print(String host, long timeMicros, String line) {
        String when = String.format(Locale.ROOT, "%10.6f", (timeMicros - start) / 1e6);
        synchronized (out) {
            out.println("trace " + when + " " + (host == null ? "" : host + " ") + line);
        }
    }

    @Override
    public void flush() {
        synchronized (out) {
            out.flush();
        }
    }
}

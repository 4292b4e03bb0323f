package org.fdnet.corba;

import java.util.Locale;
import org.fdnet.event.client.ClientStatus;

/**
 * One line on what a host holds for peers it cannot reach and how long its calls to them blocked: what
 * {@code fdnet host --health-every} prints, and what the partition soak reads to check that a silent peer costs
 * bounded memory and bounded waits.
 * <pre>
 *   fdnet host flyer health: links 1, waiting 12, lost 0, longest call 5003 ms; logger connected, in memory 40, journal 0, lost 0
 * </pre>
 * {@code waiting} is what the outgoing links hold unacknowledged (each bounded by {@link LinkSettings#capacity()}),
 * {@code longest call} the longest {@code deliver} since the previous line, {@code in memory} the events the logger
 * client holds in memory (bounded by its {@code memoryEvents}), {@code journal} those spilled to its journal.
 */
public final class HostHealth {
    /** Marks the line; the soak finds it by this. */
    public static final String MARK = " health: ";

    private HostHealth() {
    }

    /** The line for host {@code name} now; resets each link's longest call. */
    public static String line(String name, HostServant servant, RuntimeLocalNetwork engine) {
        long waiting = 0;
        long lost = 0;
        long longest = 0;
        int links = 0;
        for (OutboundLink l : servant.outboundLinks()) {
            links++;
            waiting += l.pending();
            lost += l.lost();
            longest = Math.max(longest, l.takeLongestCallMillis());
        }
        String logger = engine.logger().map(c -> {
            ClientStatus s = c.status();
            return String.format(Locale.ROOT, "logger %s, in memory %d, journal %d, lost %d",
                    s.connected() ? "connected" : "away", s.inMemory(), s.inJournal(), s.lost());
        }).orElse("logger none");
        return String.format(Locale.ROOT, "fdnet host %s%slinks %d, waiting %d, lost %d, longest call %d ms; %s", name,
                MARK, links, waiting, lost, longest, logger);
    }
}

package org.fdnet.event.client;

import java.util.Locale;

/**
 * The one line that says how a closed {@link LoggerClient} ended: every accepted event committed, or how
 * many were not confirmed or lost. {@code fdnet run} and {@code fdnet host} print it when they stop, and
 * the multi-process tests compare its count with the rows in the database.
 */
public final class CommitReport {
    private CommitReport() {
    }

    /**
     * {@code logger: all N events of run U committed}, or the counts that fell short.
     *
     * @param client a client, normally closed already (its counts are then final)
     * @return one line, without a line break
     */
    public static String of(LoggerClient client) {
        ClientStatus s = client.status();
        if (s.acked() == s.accepted() && s.lost() == 0) {
            return String.format(Locale.ROOT, "logger: all %,d events of run %s committed", s.accepted(), client.run());
        }
        return String.format(Locale.ROOT, "logger: %,d of %,d events of run %s committed, %,d not confirmed, %,d LOST%s",
                s.acked(), s.accepted(), client.run(), s.accepted() - s.acked(), s.lost(),
                s.lost() == 0 ? "" : " (journal full)");
    }
}

package org.fdnet.logger.soak;

import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.fdnet.netinfo.NodeRef;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Polls the database while the soak runs: the highest value stored end to end (an {@code Echo} value: the soak's value
 * crossed the link to the crawler, its Relay, the crawler's logger client, the logger and PostgreSQL), and the
 * number of {@code Seq} rows, which must never shrink (a committed value that disappears is a lost value).
 */
final class DeliveryWatch implements Runnable {
    private static final Logger LOG = LoggerFactory.getLogger(DeliveryWatch.class);
    private static final long PERIOD_MILLIS = 250;

    /** What one poll saw, at {@code atMillis} (epoch). */
    record Sample(long atMillis, long endToEnd) {
    }

    private final SoakDatabase database;
    private final NodeRef endToEnd;
    private final NodeRef counted;
    private final List<Sample> samples = new ArrayList<>();
    private volatile boolean stopping;
    private long mostRows;
    private long shrunk;

    DeliveryWatch(SoakDatabase database, NodeRef endToEnd, NodeRef counted) {
        this.database = database;
        this.endToEnd = endToEnd;
        this.counted = counted;
    }

    @Override
    public void run() {
        while (!stopping) {
            try {
                long highest = -1;
                for (Map.Entry<Long, Integer> e : database.copiesByValue(endToEnd).entrySet()) {
                    if (e.getValue() >= 1) {
                        highest = Math.max(highest, e.getKey());
                    }
                }
                long rows = database.rows(counted);
                synchronized (this) {
                    samples.add(new Sample(System.currentTimeMillis(), highest));
                    if (rows < mostRows) {
                        shrunk = Math.max(shrunk, mostRows - rows);
                    }
                    mostRows = Math.max(mostRows, rows);
                }
            } catch (SQLException e) {
                LOG.debug("database not answering now (a fault?): {}", e.getMessage());
            }
            try {
                Thread.sleep(PERIOD_MILLIS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return;
            }
        }
    }

    void stop() {
        stopping = true;
    }

    /** When a value of at least {@code value} was first seen stored end to end, at or after {@code fromMillis}; -1 if never. */
    synchronized long firstStored(long value, long fromMillis) {
        for (Sample s : samples) {
            if (s.atMillis() >= fromMillis && s.endToEnd() >= value) {
                return s.atMillis();
            }
        }
        return -1;
    }

    /** The most {@code Seq} rows that vanished between two polls: committed values lost (must be 0). */
    synchronized long rowsLost() {
        return shrunk;
    }
}

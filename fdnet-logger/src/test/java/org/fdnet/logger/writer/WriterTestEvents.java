package org.fdnet.logger.writer;

import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.ValueType;
import org.fdnet.logger.cache.CachedEvent;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.cache.RunProgress;
import org.fdnet.logger.store.SourceDirectory;

/** The writer tests' events (Data values of the given nodes, one a microsecond) and their wait for commits. */
final class WriterTestEvents {
    private WriterTestEvents() {
    }

    /** {@code n} events from the {@code first}-th on, round-robin over {@code ids}, sequence numbers from first + 1. */
    static List<CachedEvent> events(EventCache cache, RunProgress run, int[] ids, int first, int n) {
        List<CachedEvent> out = new ArrayList<>(n);
        for (int i = first; i < first + n; i++) {
            DataValueEvent e = new DataValueEvent(ids[i % ids.length], 1_000_000L + i, ValueType.DOUBLE, "0.5");
            out.add(new CachedEvent(e, run, i + 1, cache.sizeOf(e), System.nanoTime()));
        }
        return out;
    }

    /** Global source ids for the run's local nodes 0..n-1. */
    static int[] ids(SourceDirectory directory, RunProgress run, int n) throws SQLException {
        int[] ids = new int[n];
        for (int i = 0; i < n; i++) {
            ids[i] = directory.globalId(run, i);
        }
        return ids;
    }

    /** Waits until the cache counts {@code count} events committed. */
    static void awaitCommitted(EventCache cache, long count) throws InterruptedException {
        while (cache.committedCount() < count) {
            Thread.sleep(10);
        }
    }
}

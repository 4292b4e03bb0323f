package org.fdnet.logger.server;

import java.sql.SQLException;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import org.fdnet.event.NetworkEvent;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.store.EventStore;
import org.fdnet.logger.store.SourceDirectory;
import org.fdnet.logger.writer.BatchWriter;

/**
 * Answers a viewer's history request (thesis, chapter 4 VI): from the cache alone when it holds every
 * event of the nodes in the range, else — after asking the writer to flush what is pending, as the thesis
 * requires, and waiting for that a bounded time — from the cache and the database merged. The cache is read
 * before the database, so an event committed and evicted in between is still found in the database, and an
 * event not yet committed is still in the cache: the answer is complete even when the flush has not
 * finished. Duplicates (in both) are dropped.
 */
public final class ViewerService {
    private static final Comparator<NetworkEvent> TIME_ORDER =
            Comparator.comparingLong(NetworkEvent::time).thenComparingInt(NetworkEvent::sourceId);

    private final EventCache cache;
    private final EventStore store;
    private final SourceDirectory directory;
    private final BatchWriter writer;
    private final long flushTimeoutMillis;

    public ViewerService(EventCache cache, EventStore store, SourceDirectory directory, BatchWriter writer,
                         long flushTimeoutMillis) {
        this.cache = cache;
        this.store = store;
        this.directory = directory;
        this.writer = writer;
        this.flushTimeoutMillis = flushTimeoutMillis;
    }

    public SourceDirectory directory() {
        return directory;
    }

    public EventCache cache() {
        return cache;
    }

    public List<NetworkEvent> history(int[] sourceIds, long from, long to) throws SQLException {
        if (sourceIds.length == 1) {
            EventCache.CacheAnswer a = cache.history(sourceIds[0], from, to, directory.seenFromStart(sourceIds[0]));
            if (a.complete()) {
                return a.events(); // one node's timeline is already in time order: no copy, no sort
            }
        }
        List<NetworkEvent> cached = new ArrayList<>();
        List<Integer> incomplete = new ArrayList<>();
        for (int id : sourceIds) {
            EventCache.CacheAnswer a = cache.history(id, from, to, directory.seenFromStart(id));
            if (!a.complete()) {
                incomplete.add(id);
            }
            cached.addAll(a.events());
        }
        if (incomplete.isEmpty()) {
            cached.sort(TIME_ORDER);
            return cached;
        }
        writer.flush(flushTimeoutMillis);
        List<NetworkEvent> merged = new ArrayList<>();
        for (int id : sourceIds) {
            merged.addAll(cache.history(id, from, to, false).events());
        }
        int[] ids = incomplete.stream().mapToInt(Integer::intValue).toArray();
        Set<Key> seen = new HashSet<>();
        for (NetworkEvent e : merged) {
            seen.add(new Key(e));
        }
        for (NetworkEvent e : store.history(ids, from, to)) {
            if (seen.add(new Key(e))) {
                merged.add(e);
            }
        }
        merged.sort(TIME_ORDER);
        return merged;
    }

    private record Key(int source, long time, Class<?> kind) {
        Key(NetworkEvent e) {
            this(e.sourceId(), e.time(), e.getClass());
        }
    }
}

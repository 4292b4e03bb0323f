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
import org.fdnet.logger.store.QueryPriority;
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
    private final QueryPriority queries;

    public ViewerService(EventCache cache, EventStore store, SourceDirectory directory, BatchWriter writer,
                         long flushTimeoutMillis, QueryPriority queries) {
        this.queries = queries;
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

    /** Tells the writer and the receivers that a query is being answered (they pause while one is). */
    public QueryPriority queries() {
        return queries;
    }

    /** The answer from the cache alone, in time order; {@code null} when the cache lacks some of the range. */
    public List<NetworkEvent> fromCache(int[] sourceIds, long from, long to) {
        if (sourceIds.length == 1) {
            EventCache.CacheAnswer a = cache.history(sourceIds[0], from, to, directory.seenFromStart(sourceIds[0]));
            return a.complete() ? a.events() : null; // one node's timeline is already in time order: no copy, no sort
        }
        List<NetworkEvent> cached = new ArrayList<>();
        for (int id : sourceIds) {
            EventCache.CacheAnswer a = cache.history(id, from, to, directory.seenFromStart(id));
            if (!a.complete()) {
                return null;
            }
            cached.addAll(a.events());
        }
        cached.sort(TIME_ORDER);
        return cached;
    }

    /** The answer from the cache, or else from cache and database merged (the writer flushes first). */
    public List<NetworkEvent> history(int[] sourceIds, long from, long to) throws SQLException {
        List<NetworkEvent> cached = fromCache(sourceIds, from, to);
        if (cached != null) {
            return cached;
        }
        List<Integer> incomplete = new ArrayList<>();
        for (int id : sourceIds) {
            if (!cache.history(id, from, to, directory.seenFromStart(id)).complete()) {
                incomplete.add(id);
            }
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

package org.fdnet.logger.cache;

import java.util.ArrayList;
import java.util.Arrays;
import org.fdnet.event.NetworkEvent;

/**
 * The events of one node, sorted by time: the second level of the thesis's index (node id, then time).
 * Appending in time order (the normal case: a source's times strictly increase) is O(1); a late event is
 * inserted in place. Old events leave from the head.
 *
 * <p>Every method holds this timeline's own monitor, so a viewer's query ({@link #range}) reads it without the
 * cache's lock: it contends only with work on this one node, never with the writer's work on the others.
 * Changes come from the cache with its lock held (lock order: cache, then timeline — never the reverse).
 */
final class NodeTimeline {
    private CachedEvent[] items = new CachedEvent[8];
    private int head;
    private int tail;
    /** The newest time that ever left this timeline: below it, the database must be asked. */
    private long evictedUpTo = Long.MIN_VALUE;

    synchronized int size() {
        return tail - head;
    }

    synchronized boolean isEmpty() {
        return tail == head;
    }

    synchronized long evictedUpTo() {
        return evictedUpTo;
    }

    synchronized CachedEvent first() {
        return items[head];
    }

    synchronized void add(CachedEvent e) {
        if (tail == items.length) {
            makeRoom();
        }
        if (tail == head || items[tail - 1].time() <= e.time()) {
            items[tail++] = e;
            return;
        }
        int at = lowerBound(e.time());
        System.arraycopy(items, at, items, at + 1, tail - at);
        items[at] = e;
        tail++;
    }

    /** Removes one event (by identity), wherever it is: for the monitored index. */
    synchronized boolean remove(CachedEvent e) {
        for (int i = head; i < tail; i++) {
            if (items[i] == e) {
                System.arraycopy(items, i + 1, items, i, tail - i - 1);
                items[--tail] = null;
                return true;
            }
        }
        return false;
    }

    /** Pops evictable events from the head; returns the bytes freed. */
    synchronized long evictHead() {
        long freed = 0;
        while (head < tail && items[head].evictable()) {
            CachedEvent e = items[head];
            evictedUpTo = Math.max(evictedUpTo, e.time());
            freed += e.bytes();
            e.markLeft();
            items[head++] = null;
        }
        if (head == tail) {
            head = 0;
            tail = 0;
        }
        return freed;
    }

    /**
     * Adds the events with {@code from <= time <= to} to {@code out}, in time order, and returns
     * {@link #evictedUpTo()} as of the same instant: both read under one hold of this timeline's monitor, so
     * "nothing at or after {@code from} has left" is true of exactly the events returned. {@code out} grows
     * once, to the exact size: a viewer's query makes little garbage (its collections would pause the logger).
     * The cached events themselves: a sender reuses their kept wire bytes.
     */
    synchronized long range(long from, long to, ArrayList<CachedEvent> out) {
        int first = lowerBound(from);
        int end = firstAfter(to);
        if (end > first) {
            out.ensureCapacity(out.size() + end - first);
            for (int i = first; i < end; i++) {
                out.add(items[i]);
            }
        }
        return evictedUpTo;
    }

    private int firstAfter(long time) {
        int lo = head;
        int hi = tail;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (items[mid].time() <= time) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    private int lowerBound(long time) {
        int lo = head;
        int hi = tail;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (items[mid].time() < time) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    private void makeRoom() {
        int size = tail - head;
        if (head > 0 && size <= items.length / 2) {
            System.arraycopy(items, head, items, 0, size);
            Arrays.fill(items, size, tail, null);
        } else {
            CachedEvent[] bigger = new CachedEvent[items.length * 2];
            System.arraycopy(items, head, bigger, 0, size);
            items = bigger;
        }
        head = 0;
        tail = size;
    }
}

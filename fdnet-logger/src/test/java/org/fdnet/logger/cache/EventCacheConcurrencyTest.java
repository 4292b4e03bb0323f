package org.fdnet.logger.cache;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.ThreadLocalRandom;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.atomic.AtomicReference;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.ValueType;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The viewer's query reads a node's timeline without the cache's lock: what must still hold, and what it buys. */
@Timeout(60)
class EventCacheConcurrencyTest {
    private static final int NODES = 8;
    private static final long BASE = 1_000_000;

    private final RunProgress run = new RunProgress(1, UUID.randomUUID(), 0);
    private final AtomicLong seq = new AtomicLong();
    /** 100 bytes per event: room for 20,000, so the receiver is held back now and then while the writer evicts. */
    private final EventCache cache = new EventCache(new CacheLimits(2_000_000, 99, 99, 80, 50));

    private CachedEvent event(int source, long time) {
        NetworkEvent e = new DataValueEvent(source, time, ValueType.STRING, "x");
        return new CachedEvent(e, run, seq.incrementAndGet(), cache.sizeOf(e), System.nanoTime());
    }

    @Test
    void shouldAnswerInOrderWithoutGapsAndSayCompleteOnlyWhenItIsWhileTheWriterCommitsAndEvicts() throws Exception {
        int perNode = 40_000;
        AtomicLong addedUpTo = new AtomicLong(BASE - 1);
        AtomicReference<Throwable> failure = new AtomicReference<>();
        Thread receiver = new Thread(() -> {
            try {
                for (int i = 0; i < perNode; i += 50) {
                    List<CachedEvent> batch = new ArrayList<>();
                    for (int k = i; k < i + 50; k++) {
                        for (int node = 0; node < NODES; node++) {
                            batch.add(event(node, BASE + k));
                        }
                    }
                    cache.add(batch);
                    addedUpTo.set(BASE + i + 49);
                }
            } catch (Throwable t) {
                failure.compareAndSet(null, t);
            }
        }, "test-receiver");
        Thread writer = new Thread(() -> {
            try {
                long total = (long) perNode * NODES;
                while (cache.committedCount() < total) {
                    List<CachedEvent> batch = cache.takeBatch(1000);
                    if (batch.isEmpty()) {
                        Thread.onSpinWait();
                    } else {
                        cache.committed(batch);
                    }
                }
            } catch (Throwable t) {
                failure.compareAndSet(null, t);
            }
        }, "test-writer");
        receiver.start();
        writer.start();
        int queries = 0;
        int completeAnswers = 0;
        int incompleteAnswers = 0;
        while (writer.isAlive() && failure.get() == null) {
            long known = addedUpTo.get();
            if (known < BASE) {
                continue;
            }
            long from = ThreadLocalRandom.current().nextLong(BASE, known + 1);
            EventCache.CacheAnswer a = cache.history(3, from, Long.MAX_VALUE, true);
            List<Long> times = a.events().stream().map(NetworkEvent::time).toList();
            for (int i = 1; i < times.size(); i++) {
                assertThat(times.get(i)).as("consecutive, no gap, no duplicate").isEqualTo(times.get(i - 1) + 1);
            }
            assertThat(a.events()).allMatch(e -> e.sourceId() == 3);
            if (a.complete()) {
                completeAnswers++;
                // every event of the node at or after `from` was there before the query: all must be answered
                assertThat(times).as("a complete answer from %d", from).isNotEmpty();
                assertThat(times.get(0)).isEqualTo(from);
                assertThat(times.get(times.size() - 1)).isGreaterThanOrEqualTo(known);
            } else {
                incompleteAnswers++;
                if (!times.isEmpty()) {
                    assertThat(times.get(0)).as("an incomplete answer misses only the evicted head").isGreaterThan(from);
                }
            }
            queries++;
        }
        receiver.join();
        writer.join();
        assertThat(failure.get()).isNull();
        assertThat(queries).isGreaterThan(100);
        assertThat(completeAnswers).as("complete answers seen").isPositive();
        assertThat(incompleteAnswers).as("incomplete answers seen").isPositive();
        assertThat(cache.history(3, BASE, Long.MAX_VALUE, true).events()).isEmpty();
        assertThat(cache.status().usedBytes()).as("every committed event released").isZero();
    }

    @Test
    void shouldAnswerAQueryWhileWorkOnAnotherNodeHoldsTheCacheLock() throws Exception {
        cache.add(List.of(event(1, BASE), event(1, BASE + 1), event(1, BASE + 2)));
        CountDownLatch insideTheLock = new CountDownLatch(1);
        CountDownLatch release = new CountDownLatch(1);
        // A monitor is offered events under the cache's lock: one that stalls keeps the lock held, as a long
        // commit of another node's batch would.
        MonitorSubscriber stalling = e -> {
            insideTheLock.countDown();
            try {
                release.await();
            } catch (InterruptedException ie) {
                Thread.currentThread().interrupt();
            }
        };
        cache.subscribe(stalling, new int[] {2});
        CompletableFuture<Void> otherNode = CompletableFuture.runAsync(() -> {
            try {
                cache.add(List.of(event(2, BASE)));
            } catch (InterruptedException ie) {
                Thread.currentThread().interrupt();
            }
        });
        try {
            assertThat(insideTheLock.await(10, TimeUnit.SECONDS)).isTrue();
            CompletableFuture<Integer> lockedCall = CompletableFuture.supplyAsync(cache::unwrittenCount);
            EventCache.CacheAnswer a = CompletableFuture.supplyAsync(() -> cache.history(1, BASE + 1, Long.MAX_VALUE, true))
                    .get(5, TimeUnit.SECONDS);
            assertThat(a.events()).extracting(NetworkEvent::time).containsExactly(BASE + 1, BASE + 2);
            assertThat(a.complete()).isTrue();
            assertThat(lockedCall).as("the cache's lock really is held meanwhile").isNotDone();
        } finally {
            release.countDown();
        }
        otherNode.get(10, TimeUnit.SECONDS);
        assertThat(cache.history(2, BASE, BASE, true).events()).hasSize(1);
    }
}

package org.fdnet.logger.cache;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkCommand;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.ValueType;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class EventCacheTest {
    private final RunProgress run = new RunProgress(1, UUID.randomUUID(), 0);
    private long seq;

    /** 100 bytes per event (value "x" adds 1): capacity 10,000 → critical 8,000, normal 5,000. */
    private final EventCache cache = new EventCache(new CacheLimits(10_000, 99, 99, 80, 50));

    private List<CachedEvent> events(int source, long firstTime, int n) {
        List<CachedEvent> out = new ArrayList<>();
        for (int i = 0; i < n; i++) {
            NetworkEvent e = new DataValueEvent(source, firstTime + i, ValueType.STRING, "x");
            out.add(new CachedEvent(e, run, ++seq, cache.sizeOf(e), System.nanoTime()));
        }
        return out;
    }

    @Test
    void shouldIndexByNodeThenTimeAndMergeCommandsInOrder() throws Exception {
        cache.add(events(2, 100, 5));
        cache.add(events(3, 103, 5));
        NetworkEvent cmd = new NetworkCommandEvent(2, 102, "proc", NetworkCommand.CREATE, "9", "data");
        cache.add(List.of(new CachedEvent(cmd, run, ++seq, cache.sizeOf(cmd), System.nanoTime())));
        List<NetworkEvent> node2 = cache.history(2, 101, 103, true).events();
        assertThat(node2).extracting(NetworkEvent::time).containsExactly(101L, 102L, 102L, 103L);
        assertThat(node2).allMatch(e -> e.sourceId() == 2);
        assertThat(cache.history(2, 101, 103, true).complete()).isTrue();
        assertThat(cache.history(2, 101, 103, false).complete()).isFalse();
    }

    @Test
    void shouldKeepEventsUntilCommittedAndThenLetThemGoAndSayTheCacheNoLongerCovers() throws Exception {
        cache.add(events(1, 1000, 10));
        assertThat(cache.status().usedBytes()).isEqualTo(1000);
        List<CachedEvent> batch = cache.takeBatch(4);
        assertThat(cache.history(1, 0, Long.MAX_VALUE, true).events()).hasSize(10);
        cache.committed(batch);
        assertThat(cache.history(1, 0, Long.MAX_VALUE, true).events()).hasSize(6);
        assertThat(cache.status().usedBytes()).isEqualTo(600);
        assertThat(cache.history(1, 1003, 2000, true).complete()).isFalse();
        assertThat(cache.history(1, 1004, 2000, true).complete()).isTrue();
    }

    @Test
    void shouldHoldCommittedEventsWhileAMonitorHasNotSentThem() throws Exception {
        List<CachedEvent> offered = new ArrayList<>();
        MonitorSubscriber viewer = offered::add;
        cache.subscribe(viewer, new int[] {7});
        cache.add(events(7, 1, 3));
        cache.add(events(8, 1, 3));
        assertThat(offered).hasSize(3).allMatch(e -> e.sourceId() == 7);
        cache.committed(cache.takeBatch(6));
        assertThat(cache.history(7, 0, 10, true).events()).hasSize(3);
        assertThat(cache.history(8, 0, 10, true).events()).isEmpty();
        assertThat(cache.status().monitored()).isEqualTo(3);
        cache.delivered(offered);
        assertThat(cache.history(7, 0, 10, true).events()).isEmpty();
        assertThat(cache.status().usedBytes()).isZero();
    }

    @Test
    void shouldFreeEachCommittedEventExactlyOnceWhenNodesInterleaveInABatch() throws Exception {
        // round-robin, as a core sends: one eviction pass per node must free every event of it, and no more
        List<CachedEvent> offered = new ArrayList<>();
        cache.subscribe(offered::add, new int[] {3});
        for (int t = 0; t < 10; t++) {
            for (int node = 1; node <= 4; node++) {
                cache.add(events(node, t, 1));
            }
        }
        cache.committed(cache.takeBatch(30)); // times 0..6 of every node, 7 of nodes 1 and 2
        assertThat(cache.history(1, 0, 100, true).events()).extracting(NetworkEvent::time).containsExactly(8L, 9L);
        assertThat(cache.history(4, 0, 100, true).events()).extracting(NetworkEvent::time).containsExactly(7L, 8L, 9L);
        assertThat(cache.history(3, 0, 100, true).events()).hasSize(10); // monitored: held until sent
        assertThat(cache.status().usedBytes()).isEqualTo((40 - 30 + 7) * 100L);
        cache.delivered(offered);
        assertThat(cache.status().usedBytes()).isEqualTo(10 * 100L);
        cache.committed(cache.takeBatch(10));
        assertThat(cache.status().usedBytes()).isZero();
        assertThat(cache.status().events()).isZero();
    }

    @Test
    void shouldPressureAtTheCriticalLevelAndReleaseOnlyAtTheNormalLevel() throws Exception {
        cache.add(events(1, 0, 79));
        assertThat(cache.pressured()).isFalse();
        cache.add(events(1, 79, 1));
        assertThat(cache.pressured()).isTrue();
        cache.committed(cache.takeBatch(20)); // 6,000 bytes: below critical, above normal
        assertThat(cache.pressured()).isTrue();
        CountDownLatch resumed = new CountDownLatch(1);
        Thread receiver = new Thread(() -> {
            try {
                cache.awaitRoom();
                resumed.countDown();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        receiver.start();
        assertThat(resumed.await(300, TimeUnit.MILLISECONDS)).isFalse();
        cache.committed(cache.takeBatch(10)); // 5,000 bytes: normal level
        assertThat(resumed.await(2, TimeUnit.SECONDS)).isTrue();
        assertThat(cache.pressured()).isFalse();
    }

    @Test
    void shouldNeverGoBeyondItsCapacity() throws Exception {
        cache.add(events(1, 0, 95));
        CountDownLatch added = new CountDownLatch(1);
        Thread late = new Thread(() -> {
            try {
                cache.add(events(1, 95, 10));
                added.countDown();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        late.start();
        assertThat(added.await(300, TimeUnit.MILLISECONDS)).isFalse();
        assertThat(cache.status().usedBytes()).isLessThanOrEqualTo(10_000);
        cache.committed(cache.takeBatch(50));
        assertThat(added.await(2, TimeUnit.SECONDS)).isTrue();
        assertThat(cache.status().usedBytes()).isEqualTo(5500);
    }
}

package org.fdnet.logger.store;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Collections;
import java.util.List;
import java.util.Random;
import java.util.UUID;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.ValueType;
import org.fdnet.logger.cache.CachedEvent;
import org.fdnet.logger.cache.RunProgress;
import org.junit.jupiter.api.Test;

class CopyOrderTest {
    private final RunProgress run = new RunProgress(1, UUID.randomUUID(), 0);

    private CachedEvent event(int source, long time) {
        return new CachedEvent(new DataValueEvent(source, time, ValueType.LONG, "1"), run, 1, 1, 0);
    }

    @Test
    void shouldSortABatchByKeyEvenWithLateEvents() {
        Random random = new Random(7);
        for (boolean late : new boolean[] {false, true}) {
            List<CachedEvent> batch = new ArrayList<>();
            for (int i = 0; i < 1000; i++) {
                batch.add(event(random.nextInt(20), late && i % 100 == 0 ? i - 50 : i));
            }
            List<CachedEvent> expected = new ArrayList<>(batch);
            expected.sort((a, b) -> a.sourceId() != b.sourceId() ? Integer.compare(a.sourceId(), b.sourceId())
                    : Long.compare(a.time(), b.time()));
            Collections.shuffle(batch.subList(0, 0), random);
            EventStore.sortByKey(batch);
            assertThat(batch).extracting(CachedEvent::sourceId).isEqualTo(expected.stream().map(CachedEvent::sourceId).toList());
            assertThat(batch).extracting(CachedEvent::time).isEqualTo(expected.stream().map(CachedEvent::time).toList());
        }
    }

    @Test
    void shouldWriteCopyTextWithEscapesAndAllNumbers() {
        CopyRows rows = new CopyRows();
        rows.number(0).number(-42).number(Long.MIN_VALUE).number(Long.MAX_VALUE).text("a\tb\\c\nd\re\u00e9").endRow();
        String text = new String(rows.bytes(), 0, rows.length(), StandardCharsets.UTF_8);
        assertThat(text).isEqualTo("0\t-42\t" + Long.MIN_VALUE + "\t" + Long.MAX_VALUE + "\ta\\tb\\\\c\\nd\\re\u00e9\n");
    }

    @Test
    void shouldWriteEveryNumberAsLongToStringWould() {
        Random random = new Random(2004);
        long[] edges = {1, 9, 10, 99, 100, 101, 999, 1000, 1_700_000_000_000_000L, 999_999_999_999_999_999L,
                1_000_000_000_000_000_000L, -1, -10, -100};
        CopyRows rows = new CopyRows();
        StringBuilder expected = new StringBuilder();
        for (int i = 0; i < 2000; i++) {
            long v = i < edges.length ? edges[i] : random.nextLong() >> random.nextInt(64);
            rows.number(v).endRow();
            expected.append(v).append('\n');
        }
        assertThat(new String(rows.bytes(), 0, rows.length(), StandardCharsets.US_ASCII)).isEqualTo(expected.toString());
    }

    @Test
    void shouldFindEachRunsHighestSequenceNumberWhereRunsInterleave() {
        RunProgress other = new RunProgress(2, UUID.randomUUID(), 0);
        List<CachedEvent> batch = List.of(
                new CachedEvent(new DataValueEvent(1, 1, ValueType.LONG, "1"), run, 5, 1, 0),
                new CachedEvent(new DataValueEvent(1, 2, ValueType.LONG, "1"), run, 7, 1, 0),
                new CachedEvent(new DataValueEvent(2, 1, ValueType.LONG, "1"), other, 3, 1, 0),
                new CachedEvent(new DataValueEvent(1, 3, ValueType.LONG, "1"), run, 6, 1, 0),
                new CachedEvent(new DataValueEvent(2, 2, ValueType.LONG, "1"), other, 4, 1, 0));
        assertThat(EventStore.lastSeqByRun(batch)).containsOnly(
                org.assertj.core.api.Assertions.entry(run, 7L), org.assertj.core.api.Assertions.entry(other, 4L));
        assertThat(EventStore.lastSeqByRun(List.of())).isEmpty();
    }
}

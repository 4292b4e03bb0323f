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
}

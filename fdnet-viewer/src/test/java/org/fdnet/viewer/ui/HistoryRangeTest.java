package org.fdnet.viewer.ui;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.time.ZoneId;
import java.time.ZonedDateTime;
import org.junit.jupiter.api.Test;

class HistoryRangeTest {
    private static final ZoneId UTC = ZoneId.of("UTC");
    private static final long NEWEST = ZonedDateTime.of(2026, 11, 23, 8, 10, 0, 0, UTC).toEpochSecond() * 1_000_000L;

    @Test
    void shouldReadSecondsAsTheLastSecondsBeforeTheNewestValue() {
        assertThat(HistoryRange.parse("60", NEWEST, UTC)).containsExactly(NEWEST - 60_000_000L, NEWEST);
    }

    @Test
    void shouldReadTwoClockTimesOfTheNewestValuesDay() {
        long[] r = HistoryRange.parse("08:09:30-08:09:45.5", NEWEST, UTC);
        assertThat(r).containsExactly(NEWEST - 30_000_000L, NEWEST - 14_500_000L);
    }

    @Test
    void shouldRefuseWhatIsNeitherWithAMessageSayingWhatItExpects() {
        assertThatThrownBy(() -> HistoryRange.parse("yesterday", NEWEST, UTC)).hasMessageContaining("expected seconds");
        assertThatThrownBy(() -> HistoryRange.parse("08:10:00-08:09:00", NEWEST, UTC)).hasMessageContaining("after the start");
        assertThatThrownBy(() -> HistoryRange.parse("0", NEWEST, UTC)).hasMessageContaining("above 0");
    }
}

package org.fdnet.logger.writer;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;

class BatchSizerTest {
    @Test
    void shouldKeepTheBaseSizeWhenTheWriterKeepsUp() {
        BatchSizer sizer = new BatchSizer(1000, 100_000);
        assertThat(sizer.next(0)).isEqualTo(1000);
        assertThat(sizer.next(1000)).isEqualTo(1000);
        assertThat(sizer.next(1500)).isEqualTo(1500);
    }

    @Test
    void shouldGrowAtMostTwofoldPerBatchUpToTheMaximumUnderBacklog() {
        BatchSizer sizer = new BatchSizer(1000, 10_000);
        assertThat(sizer.next(1_000_000)).isEqualTo(2000);
        assertThat(sizer.next(1_000_000)).isEqualTo(4000);
        assertThat(sizer.next(1_000_000)).isEqualTo(8000);
        assertThat(sizer.next(1_000_000)).isEqualTo(10_000);
        assertThat(sizer.next(1_000_000)).isEqualTo(10_000);
    }

    @Test
    void shouldShrinkToTheBacklogAndBackToTheBaseWhenCaughtUp() {
        BatchSizer sizer = new BatchSizer(1000, 10_000);
        for (int i = 0; i < 5; i++) {
            sizer.next(1_000_000);
        }
        assertThat(sizer.next(3000)).isEqualTo(3000);
        assertThat(sizer.next(10)).isEqualTo(1000);
    }

    @Test
    void shouldNeverGoBelowTheBaseEvenWithASmallerMaximum() {
        BatchSizer sizer = new BatchSizer(1000, 10);
        assertThat(sizer.maxRows()).isEqualTo(1000);
        assertThat(sizer.next(1_000_000)).isEqualTo(1000);
    }
}

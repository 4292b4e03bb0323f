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

    @Test
    void shouldTakeTheWholeBacklogWithOneLane() {
        BatchSizer sizer = grown(new BatchSizer(1000, 200_000, 1));
        assertThat(sizer.next(180_000)).isEqualTo(180_000);
        assertThat(sizer.pipelineFloor()).isEqualTo(1000);
    }

    @Test
    void shouldTakeTheWholeBacklogWithSeveralLanesToo() {
        BatchSizer sizer = grown(new BatchSizer(1000, 200_000, 2));
        assertThat(sizer.next(180_000, true)).isEqualTo(180_000);
        assertThat(sizer.next(50_000, false)).isEqualTo(50_000);
    }

    @Test
    void shouldGiveABatchBesideAnotherAtLeastTheFloorHoweverSmallTheLastOne() {
        BatchSizer sizer = new BatchSizer(1000, 200_000, 2);
        assertThat(sizer.pipelineFloor()).isEqualTo(BatchSizer.PIPELINE_FLOOR_ROWS);
        assertThat(sizer.next(50_000, true)).isEqualTo(10_000);
        assertThat(sizer.next(50_000, true)).isEqualTo(20_000);
        assertThat(sizer.next(4_000, true)).as("never more than the backlog").isEqualTo(4_000);
        assertThat(sizer.next(50_000, false)).as("alone: doubling from the last").isEqualTo(8_000);
    }

    @Test
    void shouldKeepTheThesisSizeAtLowLoadWithSeveralLanes() {
        BatchSizer sizer = new BatchSizer(1000, 200_000, 2);
        assertThat(sizer.next(0, false)).isEqualTo(1000);
        assertThat(sizer.next(1000, false)).isEqualTo(1000);
        assertThat(sizer.next(1200, true)).isEqualTo(1200);
    }

    @Test
    void shouldBoundThePipelineFloorByTheBaseAndTheMaximum() {
        assertThat(new BatchSizer(1000, 4000, 2).pipelineFloor()).isEqualTo(4000);
        assertThat(new BatchSizer(20_000, 200_000, 2).pipelineFloor()).isEqualTo(20_000);
    }

    private static BatchSizer grown(BatchSizer sizer) {
        for (int i = 0; i < 20; i++) {
            sizer.next(1_000_000_000);
        }
        return sizer;
    }
}

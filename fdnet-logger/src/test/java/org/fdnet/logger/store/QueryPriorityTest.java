package org.fdnet.logger.store;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(value = 30, unit = TimeUnit.SECONDS)
class QueryPriorityTest {
    @Test
    void shouldNotWaitWhenNoQueryIsAnswered() {
        QueryPriority p = new QueryPriority(10_000);
        long t0 = System.nanoTime();
        for (int i = 0; i < 1000; i++) {
            p.yieldToQueries();
        }
        assertThat(TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - t0)).isLessThan(1000);
        assertThat(p.queried()).isFalse();
    }

    @Test
    void shouldHoldTheWriterUntilTheLastQueryEnds() throws Exception {
        QueryPriority p = new QueryPriority(10_000);
        p.begin();
        p.begin();
        AtomicLong resumedAt = new AtomicLong();
        CompletableFuture<Void> writer = CompletableFuture.runAsync(() -> {
            p.yieldToQueries();
            resumedAt.set(System.nanoTime());
        });
        Thread.sleep(100);
        p.end();
        Thread.sleep(100);
        assertThat(writer).as("one of two queries still answered").isNotDone();
        long ended = System.nanoTime();
        p.end();
        writer.get(5, TimeUnit.SECONDS);
        assertThat(resumedAt.get()).isGreaterThanOrEqualTo(ended);
    }

    @Test
    void shouldResumeAfterTheLongestPauseEvenIfAQueryNeverEnds() {
        QueryPriority p = new QueryPriority(50);
        p.begin();
        long t0 = System.nanoTime();
        p.yieldToQueries();
        long waited = TimeUnit.NANOSECONDS.toMillis(System.nanoTime() - t0);
        assertThat(waited).isBetween(45L, 5_000L);
        assertThat(p.queried()).isTrue();
    }

    @Test
    void shouldRefuseANegativePause() {
        assertThatThrownBy(() -> new QueryPriority(-1)).hasMessage("maxPauseMillis must be at least 0, was -1");
    }
}

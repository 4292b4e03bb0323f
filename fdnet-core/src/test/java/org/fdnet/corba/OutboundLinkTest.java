package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.TreeMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.corba.idl.ValueSink;
import org.fdnet.corba.idl.ValueSinkHelper;
import org.fdnet.corba.idl.ValueSinkPOA;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The sending end of a link against a sink servant in this JVM, over a real ORB. */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class OutboundLinkTest {
    private final OrbRuntime orb = OrbRuntime.start(OrbSettings.defaults().withCallTimeoutMillis(20_000));
    private OutboundLink link;

    @AfterEach
    void stop() {
        if (link != null) {
            link.close();
        }
        orb.close();
    }

    private static final OutboundLink.StateListener SILENT = new OutboundLink.StateListener() {
        @Override
        public void broken(OutboundLink l, String reason) {
        }

        @Override
        public void restored(OutboundLink l) {
        }
    };

    @Test
    void shouldBatchValuesAndFreeThemOnlyWhenAcknowledged() throws Exception {
        List<Long> batchSizes = new CopyOnWriteArrayList<>();
        // Like InboundLink: with two calls in flight a batch can arrive before the one ahead of it; it is
        // held back, and the answer is always the next sequence number expected, never more.
        ValueSink sink = ValueSinkHelper.narrow(orb.activate(new TestValueSink() {
            private final TreeMap<Long, ValueBatch> heldBack = new TreeMap<>();
            private long expected = -1;

            @Override
            public synchronized long deliver(ValueBatch batch) {
                if (expected < 0) {
                    expected = batch.firstSeq;
                }
                heldBack.put(batch.firstSeq, batch);
                while (!heldBack.isEmpty() && heldBack.firstKey() <= expected) {
                    ValueBatch next = heldBack.pollFirstEntry().getValue();
                    if (next.firstSeq == expected) {
                        batchSizes.add((long) next.values.length);
                        expected += next.values.length;
                    }
                }
                return expected;
            }
        }));
        link = new OutboundLink(1, "test#1#1", "test", sink, new LinkSettings(2, 64, 1024, 100), SILENT);

        for (long i = 0; i < 10_000; i++) {
            link.offer(i);
        }

        long deadline = System.currentTimeMillis() + 10_000;
        while (link.acknowledged() < 10_000 && System.currentTimeMillis() < deadline) {
            Thread.sleep(10);
        }
        assertThat(link.acknowledged()).isEqualTo(10_000);
        assertThat(link.pending()).isZero();
        assertThat(batchSizes.stream().mapToLong(Long::longValue).sum()).isEqualTo(10_000);
        assertThat(batchSizes).allMatch(n -> n <= 64).anyMatch(n -> n > 1);
    }

    @Test
    void shouldNotBlockAWriterForeverWhenThePeerStopsAcknowledging() throws Exception {
        CountDownLatch release = new CountDownLatch(1);
        ValueSink sink = ValueSinkHelper.narrow(orb.activate(new TestValueSink() {
            @Override
            public long deliver(ValueBatch batch) {
                try {
                    release.await(30, TimeUnit.SECONDS);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
                return batch.firstSeq + batch.values.length;
            }
        }));
        link = new OutboundLink(2, "test#1#2", "stuck", sink, new LinkSettings(1, 4, 16, 100), SILENT);

        long start = System.nanoTime();
        for (long i = 0; i < 100; i++) {
            link.offer(i);
        }
        long waitedMillis = (System.nanoTime() - start) / 1_000_000;
        release.countDown();

        assertThat(waitedMillis).isBetween(OutboundLink.MAX_WRITER_WAIT_MILLIS - 100, 15_000L);
        assertThat(link.lost()).isEqualTo(100 - 16);
    }

    @Test
    void shouldDeliverEveryValueInOrderWhetherTheSenderWatchedOrParked() throws Exception {
        // Batches may overtake each other on the ORB's threads (the InboundLink re-orders them), so this sink
        // checks that each value travels under its own sequence number: value i is written i-th.
        List<Long> received = new CopyOnWriteArrayList<>();
        List<String> misplaced = new CopyOnWriteArrayList<>();
        ValueSink sink = ValueSinkHelper.narrow(orb.activate(new TestValueSink() {
            @Override
            public long deliver(ValueBatch batch) {
                for (int i = 0; i < batch.values.length; i++) {
                    long value = (Long) ValueCodec.decode(batch.values[i]);
                    if (value != batch.firstSeq + i) {
                        misplaced.add("value " + value + " at seq " + (batch.firstSeq + i));
                    }
                    received.add(value);
                }
                return batch.firstSeq + batch.values.length;
            }
        }));
        // A 200 µs watch: the pauses below land both inside it (the watcher takes the value) and beyond it
        // (the callers have parked and offer() must wake one).
        link = new OutboundLink(3, "test#1#3", "bursts", sink, new LinkSettings(4, 8, 1024, 100, 200), SILENT);

        long next = 0;
        for (int burst = 0; burst < 300; burst++) {
            for (int i = 0; i <= burst % 20; i++) {
                link.offer(next++);
            }
            long pauseNanos = (burst % 3) * 150_000L; // 0, 150 µs, 300 µs
            long until = System.nanoTime() + pauseNanos;
            while (System.nanoTime() < until) {
                Thread.onSpinWait();
            }
        }

        // this sink answers a batch that overtook the one ahead of it at once, so the link may count a value
        // acknowledged while the call carrying it is still adding it here: wait for both
        long deadline = System.currentTimeMillis() + 20_000;
        while ((link.acknowledged() < next || received.size() < next) && System.currentTimeMillis() < deadline) {
            Thread.sleep(10);
        }
        assertThat(link.acknowledged()).isEqualTo(next);
        assertThat(misplaced).isEmpty();
        assertThat(received).hasSize((int) next).doesNotHaveDuplicates();
    }

    @Test
    void shouldParkAnIdleLinksSendersOnceTheWatchRunsOut() throws Exception {
        ValueSink sink = ValueSinkHelper.narrow(orb.activate(new TestValueSink() {
            @Override
            public long deliver(ValueBatch batch) {
                return batch.firstSeq + batch.values.length;
            }
        }));
        link = new OutboundLink(71, "test#1#71", "idle", sink, new LinkSettings(2, 8, 1024, 100, 200), SILENT);
        link.offer(1L);
        long deadline = System.currentTimeMillis() + 20_000;
        while (link.acknowledged() < 1 && System.currentTimeMillis() < deadline) {
            Thread.sleep(5);
        }
        assertThat(link.acknowledged()).isEqualTo(1);
        Thread.sleep(50); // 250 times the 200 µs watch: the link is idle now

        List<String> busy = new CopyOnWriteArrayList<>();
        for (int sample = 0; sample < 50; sample++) {
            for (Thread t : Thread.getAllStackTraces().keySet()) {
                if (t.getName().startsWith("fdnet-link-71-") && t.getState() == Thread.State.RUNNABLE) {
                    busy.add("sample " + sample + ": " + t.getName());
                }
            }
            Thread.sleep(2);
        }
        assertThat(busy).as("sender threads running while the link is idle").isEmpty();

        link.offer(2L); // a parked sender is woken for the next value
        while (link.acknowledged() < 2 && System.currentTimeMillis() < deadline) {
            Thread.sleep(5);
        }
        assertThat(link.acknowledged()).isEqualTo(2);
    }
}

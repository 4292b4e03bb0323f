package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.HashMap;
import java.util.Map;
import java.util.TreeMap;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import java.util.stream.LongStream;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.corba.idl.ValueSink;
import org.fdnet.corba.idl.ValueSinkHelper;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * An idle link's lone values sent ahead from the writer's thread (one-way), against a sink in another ORB (a remote
 * peer as far as JacORB is concerned): applied at once, acknowledged by the confirmation a sender thread sends
 * shortly after, sent again when one was lost, and a confirmation that goes unanswered breaks the link like any call.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class AheadDeliveryTest {
    private static final int REPLY_TIMEOUT_MILLIS = 400;

    private final OrbRuntime sender = OrbRuntime.start(OrbSettings.defaults().withCallTimeoutMillis(REPLY_TIMEOUT_MILLIS));
    private final OrbRuntime receiver = OrbRuntime.start(OrbSettings.defaults());
    private final List<String> states = new CopyOnWriteArrayList<>();
    private OutboundLink link;

    @AfterEach
    void stop() {
        if (link != null) {
            link.close();
        }
        sender.close();
        receiver.close();
    }

    @Test
    void shouldSendLoneValuesAheadAndFreeThemWhenAConfirmationCoversThem() throws Exception {
        RecordingSink sink = probedLink();
        link.offer(1L);
        awaitTrue(() -> sink.applied().contains(1L)); // applied before any reply came back
        assertThat(link.aheadSends()).as("the first value of an idle link goes ahead").isEqualTo(1);
        assertThat(sink.aheadCalls()).isEqualTo(1);
        for (long v = 2; v <= 20; v++) {
            link.offer(v);
            long value = v;
            awaitTrue(() -> sink.applied().contains(value));
        }
        awaitTrue(() -> link.acknowledged() == 21);

        assertThat(sink.applied()).containsExactlyElementsOf(LongStream.rangeClosed(0, 20).boxed().toList());
        // a value offered while a confirmation is in flight goes through a sender thread: how many do depends on
        // how slowly this loop runs against the confirmations' 20 ms clock
        assertThat(sink.aheadCalls()).isEqualTo((int) link.aheadSends());
        assertThat(sink.twoWayCalls()).as("the probe, then confirmations only").isBetween(2, 21);
        assertThat(link.pending()).isZero();
        assertThat(states).isEmpty();
    }

    @Test
    void shouldCarryABurstInBatchesAndNeverFloodThePeerWithValuesSentAhead() throws Exception {
        RecordingSink sink = probedLink();

        for (long v = 1; v <= 20_000; v++) {
            link.offer(v);
        }
        awaitTrue(() -> link.acknowledged() == 20_001);

        assertThat(sink.applied()).containsExactlyElementsOf(LongStream.rangeClosed(0, 20_000).boxed().toList());
        assertThat(sink.mostAheadCallsInARow()).as("one-way calls the peer took between two two-way calls")
                .isLessThanOrEqualTo(OutboundLink.AHEAD_MAX);
        assertThat(sink.twoWayCalls()).as("batches of up to 256 values").isLessThan(2_000);
    }

    @Test
    void shouldLeaveAValueToTheSenderThreadsWhenThePeerHasBeenSilentForASecond() throws Exception {
        RecordingSink sink = probedLink();

        Thread.sleep(OutboundLink.AHEAD_AFTER_REPLY_MILLIS + 200); // its connection may be closed by now
        link.offer(1L);
        awaitTrue(() -> link.acknowledged() == 2);
        link.offer(2L); // answered just now: ahead again
        awaitTrue(() -> link.acknowledged() == 3);

        assertThat(sink.applied()).containsExactly(0L, 1L, 2L);
        assertThat(link.aheadSends()).isEqualTo(1);
    }

    @Test
    void shouldSendAgainAValueLostAheadAndApplyEachValueOnceInOrder() throws Exception {
        RecordingSink sink = probedLink();

        sink.loseAheadValue(1);
        link.offer(1L); // lost on the way
        link.offer(2L); // waits for 1 at the peer
        awaitTrue(() -> link.acknowledged() == 3);

        assertThat(sink.applied()).containsExactly(0L, 1L, 2L);
        assertThat(sink.timesReceived(1)).isEqualTo(1); // only with the confirmation
        assertThat(sink.timesReceived(2)).isBetween(1, 2); // ahead or with a sender thread, maybe with the confirmation
        assertThat(states).isEmpty();
    }

    @Test
    void shouldBreakTheLinkWhenAConfirmationGoesUnansweredAndApplyItsValueOnce() throws Exception {
        RecordingSink sink = probedLink();

        sink.holdNextReplyMillis(3 * REPLY_TIMEOUT_MILLIS); // the confirmation is answered long after the timeout
        link.offer(1L);
        awaitTrue(() -> states.size() == 2 && link.acknowledged() == 2);
        for (long v = 2; v <= 10; v++) {
            link.offer(v);
        }
        awaitTrue(() -> link.acknowledged() == 11);
        Thread.sleep(3 * REPLY_TIMEOUT_MILLIS); // the late reply arrives and must settle nothing

        link.offer(11L);
        awaitTrue(() -> link.acknowledged() == 12);
        assertThat(sink.applied()).containsExactlyElementsOf(LongStream.rangeClosed(0, 11).boxed().toList());
        assertThat(link.broken()).isFalse();
        assertThat(states.get(0)).startsWith("broken: TIMEOUT");
        assertThat(states.get(1)).isEqualTo("restored");
    }

    /** A link to a new sink whose first value, 0, went through a sender thread (a new link probes its peer). */
    private RecordingSink probedLink() throws InterruptedException {
        RecordingSink sink = new RecordingSink();
        link = linkTo(sink);
        link.offer(0L);
        awaitTrue(() -> link.acknowledged() == 1);
        return sink;
    }

    private OutboundLink linkTo(RecordingSink servant) {
        String ior = receiver.orb().object_to_string(receiver.activate(servant));
        ValueSink sink = ValueSinkHelper.narrow(sender.orb().string_to_object(ior));
        return new OutboundLink(1, "test#1#1", "test link", sink, new LinkSettings(4, 256, 1 << 10, 50),
                new OutboundLink.StateListener() {
                    @Override
                    public void broken(OutboundLink l, String reason) {
                        states.add("broken: " + reason);
                    }

                    @Override
                    public void restored(OutboundLink l) {
                        states.add("restored");
                    }
                });
    }

    /**
     * Like {@link InboundLink}: applies each sequence number once, in order, holding back a batch that overtook the
     * one ahead of it; counts one-way and two-way calls, can lose a value sent ahead and hold one two-way
     * reply back after applying its batch.
     */
    private static final class RecordingSink extends TestValueSink {
        private final List<Long> applied = new ArrayList<>();
        private long expected = -1;
        private long holdMillis;
        private long loseAheadSeq = -1;
        private int aheadCalls;
        private int aheadCallsInARow;
        private int mostAheadCallsInARow;
        private int twoWayCalls;
        private final Map<Long, Integer> received = new HashMap<>();
        private final TreeMap<Long, ValueBatch> heldBack = new TreeMap<>();

        synchronized void holdNextReplyMillis(long millis) {
            holdMillis = millis;
        }

        synchronized void loseAheadValue(long seq) {
            loseAheadSeq = seq;
        }

        @Override
        public void deliverAhead(ValueBatch batch) {
            synchronized (this) {
                if (batch.firstSeq == loseAheadSeq) {
                    return;
                }
                aheadCalls++;
                aheadCallsInARow++;
                mostAheadCallsInARow = Math.max(mostAheadCallsInARow, aheadCallsInARow);
                apply(batch);
            }
        }

        @Override
        public long deliver(ValueBatch batch) {
            long hold;
            long next;
            synchronized (this) {
                twoWayCalls++;
                aheadCallsInARow = 0;
                next = apply(batch);
                hold = holdMillis;
                holdMillis = 0;
            }
            if (hold > 0) {
                try {
                    Thread.sleep(hold);
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
            return next;
        }

        private long apply(ValueBatch batch) {
            if (expected < 0) {
                expected = batch.firstSeq;
            }
            for (int i = 0; i < batch.values.length; i++) {
                received.merge(batch.firstSeq + i, 1, Integer::sum);
            }
            heldBack.put(batch.firstSeq, batch);
            while (!heldBack.isEmpty() && heldBack.firstKey() <= expected) {
                ValueBatch ready = heldBack.pollFirstEntry().getValue();
                for (int i = 0; i < ready.values.length; i++) {
                    if (ready.firstSeq + i == expected) {
                        applied.add((Long) ValueCodec.decode(ready.values[i]));
                        expected++;
                    }
                }
            }
            return expected;
        }

        synchronized List<Long> applied() {
            return new ArrayList<>(applied);
        }

        synchronized int timesReceived(long seq) {
            return received.getOrDefault(seq, 0);
        }

        synchronized int aheadCalls() {
            return aheadCalls;
        }

        synchronized int mostAheadCallsInARow() {
            return mostAheadCallsInARow;
        }

        synchronized int twoWayCalls() {
            return twoWayCalls;
        }
    }

    private void awaitTrue(BooleanSupplier condition) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(20);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("condition not met within 20 s; the link said: " + states);
            }
            Thread.sleep(5);
        }
    }
}

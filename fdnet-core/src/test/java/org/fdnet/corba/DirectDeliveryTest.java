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
import org.fdnet.corba.idl.ValueSinkPOA;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * An idle link's lone values sent from the writer's thread, against a sink in another ORB (a remote peer as far as
 * JacORB is concerned): acknowledged like any call, and a call whose reply is late is failed at the ORB's reply
 * timeout, its values sent again and applied once.
 */
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class DirectDeliveryTest {
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
    void shouldSendLoneValuesOnAnIdleLinkFromTheWritersThread() throws Exception {
        SlowSink sink = new SlowSink();
        link = linkTo(sink);

        link.offer(0L); // the first call probes the peer through a sender thread
        awaitTrue(() -> link.acknowledged() == 1);
        for (long v = 1; v <= 20; v++) {
            link.offer(v);
            long acknowledged = v + 1;
            awaitTrue(() -> link.acknowledged() == acknowledged);
        }

        assertThat(sink.applied()).containsExactlyElementsOf(LongStream.rangeClosed(0, 20).boxed().toList());
        assertThat(link.directCalls()).isEqualTo(20);
        assertThat(states).isEmpty();
    }

    @Test
    void shouldLeaveAValueToTheSenderThreadsWhenThePeerHasBeenSilentForASecond() throws Exception {
        SlowSink sink = new SlowSink();
        link = linkTo(sink);
        link.offer(0L);
        awaitTrue(() -> link.acknowledged() == 1);

        Thread.sleep(OutboundLink.DIRECT_AFTER_REPLY_MILLIS + 200); // its connection may be closed by now
        link.offer(1L);
        awaitTrue(() -> link.acknowledged() == 2);
        link.offer(2L); // answered just now: direct again
        awaitTrue(() -> link.acknowledged() == 3);

        assertThat(sink.applied()).containsExactly(0L, 1L, 2L);
        assertThat(link.directCalls()).isEqualTo(1);
    }

    @Test
    void shouldFailADirectCallWhoseReplyIsLateAndApplyItsValueOnce() throws Exception {
        SlowSink sink = new SlowSink();
        link = linkTo(sink);
        link.offer(0L);
        awaitTrue(() -> link.acknowledged() == 1);

        sink.holdNextReplyMillis(3 * REPLY_TIMEOUT_MILLIS); // applied at once, answered long after the timeout
        link.offer(1L);
        awaitTrue(() -> states.contains("broken: no reply within " + REPLY_TIMEOUT_MILLIS + " ms"));
        awaitTrue(() -> link.acknowledged() == 2 && states.contains("restored"));
        for (long v = 2; v <= 10; v++) {
            link.offer(v);
        }
        awaitTrue(() -> link.acknowledged() == 11);
        Thread.sleep(3 * REPLY_TIMEOUT_MILLIS); // the late reply arrives and must settle nothing

        link.offer(11L);
        awaitTrue(() -> link.acknowledged() == 12);
        assertThat(sink.applied()).containsExactlyElementsOf(LongStream.rangeClosed(0, 11).boxed().toList());
        assertThat(sink.timesReceived(1)).isEqualTo(2); // once answered late, once sent again
        assertThat(link.broken()).isFalse();
        assertThat(states).containsExactly("broken: no reply within " + REPLY_TIMEOUT_MILLIS + " ms", "restored");
    }

    private OutboundLink linkTo(SlowSink servant) {
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
     * one ahead of it (a direct call and a sender thread's call can reach the wire in either order); can hold one
     * reply back after applying its batch.
     */
    private static final class SlowSink extends ValueSinkPOA {
        private final List<Long> applied = new ArrayList<>();
        private long expected = -1;
        private long holdMillis;
        private final Map<Long, Integer> received = new HashMap<>();
        private final TreeMap<Long, ValueBatch> heldBack = new TreeMap<>();

        synchronized void holdNextReplyMillis(long millis) {
            holdMillis = millis;
        }

        @Override
        public long deliver(ValueBatch batch) {
            long hold;
            long next;
            synchronized (this) {
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
                hold = holdMillis;
                holdMillis = 0;
                next = expected;
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

        synchronized List<Long> applied() {
            return new ArrayList<>(applied);
        }

        synchronized int timesReceived(long seq) {
            return received.getOrDefault(seq, 0);
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

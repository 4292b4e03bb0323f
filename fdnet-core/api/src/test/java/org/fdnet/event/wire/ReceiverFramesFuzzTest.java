package org.fdnet.event.wire;

import static org.assertj.core.api.Assertions.assertThat;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.event.NetworkEvent;

/**
 * Fuzzes what the logger's receiver decodes from a core's connection, in its order: frames ({@link FrameReader}),
 * the HELLO ({@link Hello#read}), then RUN frames ({@link RunFrame#read}) and EVENTS frames checked whole ({@link EventsFrame#check}) and their events
 * ({@link EventCodec#read(Frame, EventCodec.SourceIdMap)}). Any bytes decode or fail with a
 * {@link ProtocolException} (the receiver logs it and closes that one connection) — never another exception, a
 * buffer the length prefix merely claims, or a hang. Every accepted frame's events, encoded again as a core
 * encodes them, decode to the same events. Seeds and kept findings:
 * {@code src/test/resources/org/fdnet/event/wire/ReceiverFramesFuzzTestInputs/}.
 */
class ReceiverFramesFuzzTest {
    /** Small enough that the fuzzer reaches the limit, as a real peer reaches the logger's. */
    static final int MAX_FRAME_BYTES = 1 << 16;

    @FuzzTest(maxDuration = "10m")
    void shouldTakeOrRefuseCoreFrames(byte[] input) throws IOException {
        FrameReader in = new FrameReader(new ByteArrayInputStream(input), MAX_FRAME_BYTES);
        try {
            Frame first = in.read();
            if (first == null) {
                return;
            }
            Hello hello = Hello.read(first);
            assertThat(hello.name()).isNotNull();
            Frame f;
            while ((f = in.read()) != null) {
                if (f.type() == MessageType.RUN) {
                    assertThat(RunFrame.read(f).host()).isNotNull();
                    continue;
                }
                EventsFrame events = EventsFrame.check(f);
                List<NetworkEvent> taken = take(f, events.count());
                assertThat(again(events.firstSeq(), taken)).isEqualTo(taken);
            }
        } catch (ProtocolException refused) {
            assertThat(refused.getMessage()).isNotBlank();
        }
    }

    private static List<NetworkEvent> take(Frame f, int count) throws ProtocolException {
        List<NetworkEvent> taken = new ArrayList<>(count);
        for (int i = 0; i < count; i++) {
            try {
                taken.add(EventCodec.read(f, id -> id));
            } catch (InterruptedException e) {
                throw new AssertionError("an identity map never waits", e);
            }
        }
        f.expectEnd();
        return taken;
    }

    /** The events as a core's logger client frames them, read back. */
    private static List<NetworkEvent> again(long firstSeq, List<NetworkEvent> events) throws IOException {
        FrameWriter w = new FrameWriter().begin(MessageType.EVENTS).putLong(firstSeq).putInt(events.size());
        events.forEach(e -> EventCodec.write(w, e));
        Frame f = new FrameReader(new ByteArrayInputStream(w.toBytes()), Integer.MAX_VALUE).read();
        EventsFrame checked = EventsFrame.check(f);
        assertThat(checked.firstSeq()).isEqualTo(firstSeq);
        return take(f, checked.count());
    }
}

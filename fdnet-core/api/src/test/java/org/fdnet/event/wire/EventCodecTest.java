package org.fdnet.event.wire;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.Arrays;
import java.util.List;
import java.util.UUID;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkCommand;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.event.TypedValue;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.Test;

class EventCodecTest {
    private static final List<NetworkEvent> ALL = List.of(
            new DataValueEvent(3, 11L, TypedValue.of(true)),
            new DataValueEvent(3, 12L, TypedValue.of(Long.MIN_VALUE)),
            new DataValueEvent(3, 13L, TypedValue.of(0.1 + 0.2)),
            new DataValueEvent(3, 14L, TypedValue.of("\u00e9\u4e2d\ttab")),
            new DataValueEvent(3, 15L, TypedValue.ofBytes(new byte[] {0, -1, 7})),
            new DataValueEvent(3, 16L, TypedValue.ofDoubles()),
            new DataValueEvent(3, 17L, TypedValue.ofDoubles(0.5, 1.5, Double.NEGATIVE_INFINITY)),
            new RelationValueEvent(4, 18L, "FAILED: java.lang.ArithmeticException: / by zero"),
            new NetworkCommandEvent(0, 19L, "controller", NetworkCommand.UNLOAD, "arm", "module"),
            new NodeNamedEvent(5, 20L, NodeKind.RELATION, new NodeRef("main", "Planner")));

    private static byte[] frame(List<NetworkEvent> events) throws IOException {
        FrameWriter w = new FrameWriter();
        w.begin(MessageType.EVENTS).putLong(1).putInt(events.size());
        events.forEach(e -> EventCodec.write(w, e));
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        w.writeTo(out);
        return out.toByteArray();
    }

    @Test
    void shouldDecodeEveryEventKindExactlyAsEncoded() throws IOException {
        Frame f = new FrameReader(new ByteArrayInputStream(frame(ALL)), Protocol.DEFAULT_MAX_FRAME_BYTES).read();
        assertThat(f.type()).isEqualTo(MessageType.EVENTS);
        assertThat(f.getLong()).isEqualTo(1);
        int n = f.getCount(EventCodec.MIN_EVENT_BYTES);
        NetworkEvent[] decoded = new NetworkEvent[n];
        for (int i = 0; i < n; i++) {
            decoded[i] = EventCodec.read(f);
        }
        f.expectEnd();
        assertThat(Arrays.asList(decoded)).isEqualTo(ALL);
    }

    @Test
    void shouldReportATruncatedFrameAsTruncated() throws IOException {
        byte[] whole = frame(ALL);
        byte[] cut = Arrays.copyOf(whole, whole.length - 7);
        assertThatThrownBy(() -> new FrameReader(new ByteArrayInputStream(cut), 1 << 20).read())
                .isInstanceOf(ProtocolException.class).hasMessageContaining("truncated frame");
    }

    @Test
    void shouldRefuseAnOversizedFrameBeforeReadingIt() throws IOException {
        byte[] whole = frame(ALL);
        assertThatThrownBy(() -> new FrameReader(new ByteArrayInputStream(whole), 16).read())
                .isInstanceOf(ProtocolException.class).hasMessageContaining("outside 1..16");
    }

    @Test
    void shouldRejectACountThatCannotFitTheFrame() throws IOException {
        FrameWriter w = new FrameWriter();
        w.begin(MessageType.EVENTS).putLong(1).putInt(1_000_000);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        w.writeTo(out);
        Frame f = new FrameReader(new ByteArrayInputStream(out.toByteArray()), 1 << 20).read();
        f.getLong();
        assertThatThrownBy(() -> f.getCount(EventCodec.MIN_EVENT_BYTES)).isInstanceOf(ProtocolException.class)
                .hasMessageContaining("count 1000000");
    }

    @Test
    void shouldRejectAHelloWithTheWrongMagicOrAnUnknownType() throws IOException {
        FrameWriter w = new FrameWriter();
        w.begin(MessageType.HELLO).putInt(0x12345678).putShort(1).putByte(1).putLong(0).putLong(0).putString("x");
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        w.writeTo(out);
        Frame f = new FrameReader(new ByteArrayInputStream(out.toByteArray()), 1 << 20).read();
        assertThatThrownBy(() -> Hello.read(f)).hasMessageContaining("bad magic");
        byte[] unknown = {0, 0, 0, 1, (byte) 200};
        assertThatThrownBy(() -> new FrameReader(new ByteArrayInputStream(unknown), 1 << 20).read())
                .hasMessageContaining("unknown frame type 200");
    }

    @Test
    void shouldRoundTripAHello() throws IOException {
        UUID run = UUID.randomUUID();
        FrameWriter w = new FrameWriter();
        Hello.core(run, "robot-1").write(w);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        w.writeTo(out);
        Hello h = Hello.read(new FrameReader(new ByteArrayInputStream(out.toByteArray()), 1 << 20).read());
        assertThat(h).isEqualTo(Hello.core(run, "robot-1"));
    }

    private static Frame eventsOf(byte[] bytes) throws IOException {
        Frame f = new FrameReader(new ByteArrayInputStream(bytes), Protocol.DEFAULT_MAX_FRAME_BYTES).read();
        f.getLong();
        return f;
    }

    @Test
    void shouldBuildEachEventOnceWithItsMappedSourceAsReadThenWithSourceWould() throws Exception {
        Frame f = eventsOf(frame(ALL));
        int n = f.getCount(EventCodec.MIN_EVENT_BYTES);
        NetworkEvent[] mapped = new NetworkEvent[n];
        for (int i = 0; i < n; i++) {
            mapped[i] = EventCodec.read(f, id -> 1000 + id);
        }
        f.expectEnd();
        assertThat(Arrays.asList(mapped)).isEqualTo(ALL.stream().map(e -> EventCodec.withSource(e, 1000 + e.sourceId())).toList());
    }

    @Test
    void shouldSkipExactlyTheBytesReadWouldRead() throws IOException {
        Frame f = eventsOf(frame(ALL));
        int n = f.getCount(EventCodec.MIN_EVENT_BYTES);
        int start = f.position();
        int[] afterRead = new int[n];
        for (int i = 0; i < n; i++) {
            EventCodec.read(f);
            afterRead[i] = f.position();
        }
        f.rewind(start);
        for (int i = 0; i < n; i++) {
            EventCodec.skip(f);
            assertThat(f.position()).isEqualTo(afterRead[i]);
        }
        f.expectEnd();
    }

    @Test
    void shouldRejectInSkipEveryMalformedEventThatReadRejects() throws IOException {
        // kind, value type, boolean, counts, command, node kind and a string longer than the frame: skip must fail
        // where read fails, with the same message
        List<byte[]> bad = List.of(
                eventBytes(w -> w.putEventHead(9, 1, 2L).putString("x")),
                eventBytes(w -> w.putEventHead(1, 1, 2L).putByte(77).putString("x")),
                eventBytes(w -> w.putEventHead(1, 1, 2L).putByte(1).putByte(2)),
                eventBytes(w -> w.putEventHead(1, 1, 2L).putByte(6).putInt(3).putLong(0).putLong(0)),
                eventBytes(w -> w.putEventHead(1, 1, 2L).putByte(5).putInt(-1)),
                eventBytes(w -> w.putEventHead(1, 1, 2L).putByte(3).putInt(0)),
                eventBytes(w -> w.putEventHead(3, 1, 2L).putString("t").putByte(200).putString("p").putString("q")),
                eventBytes(w -> w.putEventHead(4, 1, 2L).putByte(3).putString("m").putString("n")),
                eventBytes(w -> w.putEventHead(2, 1, 2L).putInt(5000)));
        for (byte[] b : bad) {
            Frame forRead = eventsOf(b);
            forRead.getCount(EventCodec.MIN_EVENT_BYTES);
            Frame forSkip = eventsOf(b);
            forSkip.getCount(EventCodec.MIN_EVENT_BYTES);
            Throwable byRead = org.assertj.core.api.Assertions.catchThrowable(() -> EventCodec.read(forRead));
            assertThat(byRead).isInstanceOf(ProtocolException.class);
            assertThatThrownBy(() -> EventCodec.skip(forSkip)).isInstanceOf(ProtocolException.class)
                    .hasMessage(byRead.getMessage());
        }
    }

    @Test
    void shouldSendEachNumberAsItsEightBytes() throws IOException {
        FrameWriter w = new FrameWriter().begin(MessageType.EVENTS);
        int mark = w.position();
        EventCodec.write(w, new DataValueEvent(1, 2L, TypedValue.of(0.1 + 0.2)));
        EventCodec.write(w, new DataValueEvent(1, 3L, TypedValue.of(-5L)));
        byte[] b = w.bytesSince(mark);
        assertThat(b).hasSize(2 * (13 + 1 + 8)); // head, value type, the number
        assertThat(b[13]).isEqualTo((byte) 3);
        assertThat(java.nio.ByteBuffer.wrap(b, 14, 8).getLong()).isEqualTo(Double.doubleToRawLongBits(0.1 + 0.2));
        assertThat(b[22 + 13]).isEqualTo((byte) 2);
        assertThat(java.nio.ByteBuffer.wrap(b, 22 + 14, 8).getLong()).isEqualTo(-5L);
    }

    private static byte[] eventBytes(java.util.function.Consumer<FrameWriter> event) throws IOException {
        FrameWriter w = new FrameWriter();
        w.begin(MessageType.EVENTS).putLong(1).putInt(1);
        event.accept(w);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        w.writeTo(out);
        return out.toByteArray();
    }
}

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
import org.fdnet.event.ValueType;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.Test;

class EventCodecTest {
    private static final List<NetworkEvent> ALL = List.of(
            new DataValueEvent(3, 17L, ValueType.DOUBLES, "0.5,1.5,\u00e9\u4e2d"),
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
}

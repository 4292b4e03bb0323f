package org.fdnet.event.wire;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkCommand;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.event.TypedValue;
import org.fdnet.event.ValueType;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.Test;

class HistoryColumnsTest {
    private static Frame chunk(List<NetworkEvent> events) throws IOException {
        FrameWriter w = new FrameWriter();
        w.begin(MessageType.HISTORY_CHUNK).putInt(7).putInt(events.size());
        events.forEach(e -> EventCodec.write(w, e));
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        w.writeTo(out);
        Frame f = new FrameReader(new ByteArrayInputStream(out.toByteArray()), Protocol.DEFAULT_MAX_FRAME_BYTES).read();
        assertThat(f.getInt()).isEqualTo(7);
        return f;
    }

    private static HistoryColumns read(Frame f) throws ProtocolException {
        HistoryColumns c = new HistoryColumns();
        int n = f.getCount(EventCodec.MIN_EVENT_BYTES);
        c.reserve(n);
        for (int i = 0; i < n; i++) {
            c.append(f);
        }
        f.expectEnd();
        return c;
    }

    @Test
    void shouldGiveBackEveryEventAsEncodedAndTheNumbersOfLongAndDoubleValues() throws IOException {
        List<NetworkEvent> events = new ArrayList<>(List.of(
                new NodeNamedEvent(5, 1L, NodeKind.DATA, new NodeRef("arm", "Joint")),
                new DataValueEvent(5, 2L, ValueType.DOUBLE, "0.25"),
                new DataValueEvent(5, 3L, ValueType.LONG, "-42"),
                new DataValueEvent(5, 4L, TypedValue.of("not a number \u00e9")),
                new DataValueEvent(5, 5L, ValueType.DOUBLES, "0.5,1.5"),
                new DataValueEvent(5, 6L, ValueType.BOOLEAN, "true"),
                new RelationValueEvent(6, 7L, "RUNNING"),
                new NetworkCommandEvent(0, 8L, "controller", NetworkCommand.UNLOAD, "arm", "module"),
                new DataValueEvent(5, 9L, ValueType.DOUBLE, "0.30000000000000004")));
        for (int i = 0; i < 3000; i++) { // more than the first arrays hold
            events.add(new DataValueEvent(9, 100L + i, ValueType.DOUBLE, Double.toString(i * 0.001)));
        }
        HistoryColumns c = read(chunk(events));

        assertThat(c.size()).isEqualTo(events.size());
        assertThat(c.events()).isEqualTo(events);
        assertThat(c.hasNumber(1)).isTrue();
        assertThat(c.number(1)).isEqualTo(0.25);
        assertThat(c.number(2)).isEqualTo(-42.0);
        assertThat(c.hasNumber(3)).isFalse();
        assertThat(c.text(3)).isEqualTo("not a number \u00e9");
        assertThat(c.valueType(3)).isEqualTo(ValueType.STRING);
        assertThat(c.hasNumber(4)).isFalse();
        assertThat(c.hasNumber(5)).isFalse();
        assertThat(c.isDataValue(6)).isFalse();
        assertThat(c.text(7)).isNull();
        assertThat(c.number(8)).isEqualTo(0.30000000000000004);
        for (int i = 0; i < 3000; i++) {
            assertThat(c.number(9 + i)).isEqualTo(i * 0.001);
            assertThat(c.time(9 + i)).isEqualTo(100L + i);
            assertThat(c.sourceId(9 + i)).isEqualTo(9);
        }
        assertThat(c.valueType(5)).isEqualTo(ValueType.BOOLEAN);
        assertThatThrownBy(() -> c.number(3)).isInstanceOf(IllegalStateException.class);
        assertThatThrownBy(() -> c.time(events.size())).isInstanceOf(IndexOutOfBoundsException.class);
    }

    @Test
    void shouldCarryNumbersInBinaryExactlyAndReadThemInPlace() throws IOException {
        List<NetworkEvent> events = List.of(
                new DataValueEvent(1, 1L, TypedValue.of(0.25)),
                new DataValueEvent(1, 2L, TypedValue.of(-0.0)),
                new DataValueEvent(1, 3L, TypedValue.of(Double.NaN)),
                new DataValueEvent(1, 4L, TypedValue.of(1.0E-7)),
                new DataValueEvent(1, 5L, TypedValue.of(Long.MAX_VALUE)), // beyond a double's exact longs: still exact
                new DataValueEvent(1, 6L, TypedValue.of(0.1 + 0.2)),
                new DataValueEvent(1, 7L, TypedValue.of("12")),
                new DataValueEvent(1, 8L, TypedValue.ofDoubles(0.5, -1.5)),
                new RelationValueEvent(2, 9L, "RUNNING"));
        FrameWriter w = new FrameWriter();
        w.begin(MessageType.HISTORY_CHUNK).putInt(7).putInt(events.size());
        int[] sizes = new int[events.size()];
        for (int i = 0; i < events.size(); i++) {
            int mark = w.position();
            EventCodec.write(w, events.get(i));
            sizes[i] = w.position() - mark;
        }
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        w.writeTo(out);
        Frame f = new FrameReader(new ByteArrayInputStream(out.toByteArray()), Protocol.DEFAULT_MAX_FRAME_BYTES).read();
        f.getInt();
        HistoryColumns c = new HistoryColumns();
        c.appendAll(f, f.getCount(EventCodec.MIN_EVENT_BYTES));
        f.expectEnd();

        assertThat(sizes).containsExactly(22, 22, 22, 22, 22, 22, 20, 34, 24);
        assertThat(c.events()).isEqualTo(events);
        assertThat(c.number(0)).isEqualTo(0.25);
        assertThat(Double.doubleToRawLongBits(c.number(1))).isEqualTo(Double.doubleToRawLongBits(-0.0));
        assertThat(c.number(2)).isNaN();
        assertThat(c.text(3)).isEqualTo("1.0E-7");
        assertThat(c.text(4)).isEqualTo(Long.toString(Long.MAX_VALUE));
        assertThat(c.number(5)).isEqualTo(0.1 + 0.2);
        assertThat(c.hasNumber(6)).isFalse();
        assertThat(c.text(6)).isEqualTo("12");
        assertThat(c.hasNumber(7)).isFalse();
        assertThat(c.valueType(7)).isEqualTo(ValueType.DOUBLES);
        assertThat(c.text(8)).isEqualTo("RUNNING");
        assertThat(c.valueType(4)).isEqualTo(ValueType.LONG);
    }

    @Test
    void shouldRejectAnUnknownValueTypeNamingTheFrame() throws IOException {
        FrameWriter w = new FrameWriter();
        w.begin(MessageType.HISTORY_CHUNK).putInt(1).putInt(1).putEventHead(1, 3, 10L).putByte(99).putLong(1);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        w.writeTo(out);
        Frame f = new FrameReader(new ByteArrayInputStream(out.toByteArray()), Protocol.DEFAULT_MAX_FRAME_BYTES).read();
        f.getInt();
        assertThatThrownBy(() -> read(f)).isInstanceOf(ProtocolException.class).hasMessageContaining("value type code 99");
    }

    @Test
    void shouldRejectAStringLongerThanTheFrame() throws IOException {
        FrameWriter w = new FrameWriter();
        w.begin(MessageType.HISTORY_CHUNK).putInt(1).putInt(1).putEventHead(2, 3, 10L).putInt(1000).putByte('x')
                .putLong(0).putLong(0);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        w.writeTo(out);
        Frame f = new FrameReader(new ByteArrayInputStream(out.toByteArray()), Protocol.DEFAULT_MAX_FRAME_BYTES).read();
        f.getInt();
        assertThatThrownBy(() -> read(f)).isInstanceOf(ProtocolException.class)
                .hasMessageContaining("malformed HISTORY_CHUNK frame: string of 1000 bytes");
    }
}

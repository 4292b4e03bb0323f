package org.fdnet.viewer.data;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayInputStream;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.event.TypedValue;
import org.fdnet.event.ValueType;
import org.fdnet.event.wire.EventCodec;
import org.fdnet.event.wire.Frame;
import org.fdnet.event.wire.FrameReader;
import org.fdnet.event.wire.FrameWriter;
import org.fdnet.event.wire.HistoryColumns;
import org.fdnet.event.wire.MessageType;
import org.fdnet.event.wire.Protocol;
import org.junit.jupiter.api.Test;

class PlotDataHistoryTest {
    private static HistoryColumns columns(List<NetworkEvent> events) throws IOException {
        FrameWriter w = new FrameWriter();
        w.begin(MessageType.HISTORY_CHUNK).putInt(events.size());
        events.forEach(e -> EventCodec.write(w, e));
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        w.writeTo(out);
        Frame f = new FrameReader(new ByteArrayInputStream(out.toByteArray()), Protocol.DEFAULT_MAX_FRAME_BYTES).read();
        HistoryColumns c = new HistoryColumns();
        int n = f.getCount(EventCodec.MIN_EVENT_BYTES);
        for (int i = 0; i < n; i++) {
            c.append(f);
        }
        return c;
    }

    private static PlotData tracking() {
        PlotData p = new PlotData();
        p.track(1, "double", "m");
        p.track(2, "long", "");
        p.track(3, "flag", "");
        p.track(4, "posture", "rad");
        p.track(5, "text", "");
        return p;
    }

    @Test
    void shouldPlotAHistoryAnswerExactlyAsItsEventsOneByOne() throws IOException {
        List<NetworkEvent> events = new ArrayList<>();
        for (int i = 0; i < 500; i++) {
            long t = 1000L + i;
            // now and then a value the logger could only give back as text (a stored row that was not a number)
            events.add(i % 50 == 7 ? new DataValueEvent(1, t, TypedValue.of("oops"))
                    : new DataValueEvent(1, t, TypedValue.of(Math.sin(i))));
            events.add(new DataValueEvent(2, t, ValueType.LONG, Long.toString(i * 1_000_003L)));
            events.add(new DataValueEvent(3, t, ValueType.BOOLEAN, i % 3 == 0 ? "true" : "false"));
            events.add(new DataValueEvent(4, t, ValueType.DOUBLES, i + "," + (i * 0.5) + (i > 250 ? ",1" : "")));
            events.add(new DataValueEvent(5, t, ValueType.STRING, "state " + i));
            events.add(new DataValueEvent(9, t, ValueType.DOUBLE, "1.5")); // not tracked
            events.add(new RelationValueEvent(1, t, "RUNNING"));
        }
        PlotData oneByOne = tracking();
        events.forEach(oneByOne::accept);
        PlotData fromColumns = tracking();
        fromColumns.accept(columns(events));

        assertThat(fromColumns.acceptedEvents()).isEqualTo(oneByOne.acceptedEvents()).isEqualTo(500 - 10 + 500 * 3);
        assertThat(fromColumns.ignoredEvents()).isEqualTo(oneByOne.ignoredEvents());
        assertThat(fromColumns.series()).hasSameSizeAs(oneByOne.series()).hasSize(1 + 1 + 1 + 3);
        for (int s = 0; s < oneByOne.series().size(); s++) {
            Series a = oneByOne.series().get(s);
            Series b = fromColumns.series().get(s);
            assertThat(b.name()).isEqualTo(a.name());
            Series.Samples sa = a.range(Long.MIN_VALUE, Long.MAX_VALUE);
            Series.Samples sb = b.range(Long.MIN_VALUE, Long.MAX_VALUE);
            assertThat(sb.times()).as(a.name()).isEqualTo(sa.times());
            assertThat(sb.values()).as(a.name()).isEqualTo(sa.values());
        }
    }
}

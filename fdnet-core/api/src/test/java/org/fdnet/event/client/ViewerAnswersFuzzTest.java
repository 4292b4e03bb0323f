package org.fdnet.event.client;

import static org.assertj.core.api.Assertions.assertThat;

import com.code_intelligence.jazzer.junit.FuzzTest;
import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.ValueType;
import org.fdnet.event.wire.Frame;
import org.fdnet.event.wire.FrameReader;
import org.fdnet.event.wire.FrameWriter;
import org.fdnet.event.wire.HistoryColumns;
import org.fdnet.event.wire.ProtocolException;
import org.fdnet.event.wire.ViewerRequest;

/**
 * Fuzzes both directions of a viewer's connection to the logger's sender port. First byte odd: the requests the
 * logger reads ({@link ViewerRequest#read}), each refused with a {@link ProtocolException} or written again as
 * the viewer writes it and read back equal. First byte even: what a viewer decodes from the logger
 * ({@link LoggerAnswers} behind {@link ViewerClient}): frames with history chunks (as events for request 1, as {@link HistoryColumns} for request 2), history ends,
 * node lists, monitored events and errors. Any bytes are taken or fail with an {@link IOException} — a
 * {@link ProtocolException} naming what was malformed, or the logger's own ERROR reason — never another
 * exception, a buffer a count merely claims, or a hang. Every event a chunk put in columns must read back (as
 * an event, as text), and a value held as a number must be the number its text says. Seeds and kept findings:
 * {@code src/test/resources/org/fdnet/event/client/ViewerAnswersFuzzTestInputs/}.
 */
class ViewerAnswersFuzzTest {
    private static final int MAX_FRAME_BYTES = 1 << 16;

    @FuzzTest(maxDuration = "10m")
    void shouldTakeOrRefuseLoggerAnswers(byte[] input) throws IOException {
        if (input.length == 0) {
            return;
        }
        FrameReader in = new FrameReader(new ByteArrayInputStream(input, 1, input.length - 1), MAX_FRAME_BYTES);
        if ((input[0] & 1) == 1) {
            requests(in);
        } else {
            answers(in);
        }
    }

    private static void requests(FrameReader in) throws IOException {
        try {
            Frame f;
            while ((f = in.read()) != null) {
                ViewerRequest r = ViewerRequest.read(f);
                FrameWriter w = new FrameWriter();
                r.write(w);
                ViewerRequest again = ViewerRequest.read(new FrameReader(new ByteArrayInputStream(w.toBytes()),
                        Integer.MAX_VALUE).read());
                assertThat(again).usingRecursiveComparison().isEqualTo(r);
            }
        } catch (ProtocolException refused) {
            assertThat(refused.getMessage()).isNotBlank();
        }
    }

    private static void answers(FrameReader in) {
        List<NetworkEvent> monitored = new ArrayList<>();
        LoggerAnswers answers = new LoggerAnswers(monitored::add);
        LoggerAnswers.Request events = new LoggerAnswers.Request(null);
        LoggerAnswers.Request columns = new LoggerAnswers.Request(new HistoryColumns());
        answers.open(1, events);
        answers.open(2, columns);
        try {
            Frame f;
            while ((f = in.read()) != null) {
                answers.dispatch(f);
            }
        } catch (IOException refused) {
            assertThat(refused.getMessage()).isNotBlank();
        }
        assertThat(events.items).doesNotContainNull();
        assertThat(monitored).doesNotContainNull();
        HistoryColumns c = columns.columns;
        for (int i = 0; i < c.size(); i++) {
            assertThat(c.event(i)).isNotNull();
            if (c.isDataValue(i)) {
                assertThat(c.text(i)).isNotNull();
                assertThat(c.valueType(i)).isNotNull();
            }
            if (c.hasNumber(i)) {
                String text = c.text(i).trim();
                double said = c.valueType(i) == ValueType.LONG ? Long.parseLong(text) : Double.parseDouble(text);
                assertThat(Double.compare(said, c.number(i)))
                        .as("event %d's number is its text %s", i, c.text(i)).isZero();
            }
        }
    }
}

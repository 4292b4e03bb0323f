package org.fdnet.logger;

import org.fdnet.event.DataValueEvent;
import org.fdnet.event.EventClock;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkCommand;
import org.fdnet.event.NetworkCommandEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.event.TypedValue;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/** A small synthetic core: names its nodes, then writes values, statuses and commands. */
final class TestEvents {
    private final EventClock clock = new EventClock();
    private final int datas;
    private long produced;

    TestEvents(int datas) {
        this.datas = datas;
    }

    void name(EventSink sink) {
        for (int i = 0; i < datas; i++) {
            sink.accept(new NodeNamedEvent(i, clock.next(), NodeKind.DATA, new NodeRef("arm", "Joint" + i)));
        }
        sink.accept(new NodeNamedEvent(datas, clock.next(), NodeKind.RELATION, new NodeRef("arm", "Controller")));
    }

    /** One value (a string with a tab and newline now and then, to exercise COPY escaping), a status, or a command. */
    void produce(EventSink sink) {
        long i = produced++;
        if (i % 50 == 49) {
            sink.accept(new RelationValueEvent(datas, clock.next(), "RUNNING\tstep " + i));
        } else if (i % 500 == 499) {
            sink.accept(new NetworkCommandEvent(datas, clock.next(), "proc", NetworkCommand.CONNECT, "3>" + datas, "reader"));
        } else {
            // doubles with a short text (i * 0.25) and with 17 digits (0.30000000000000004 = 3 * 0.1), a string now and then
            TypedValue v = i % 97 == 0 ? TypedValue.of("line\\one\nline two\u00e9")
                    : TypedValue.of(i % 2 == 0 ? i * 0.25 : i * 0.1);
            sink.accept(new DataValueEvent((int) (i % datas), clock.next(), v));
        }
    }

    long produced() {
        return produced;
    }
}

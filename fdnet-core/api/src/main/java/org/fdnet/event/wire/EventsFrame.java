package org.fdnet.event.wire;

/**
 * An EVENTS frame ({@code i64 firstSeq, i32 count, events}) checked whole before any of it is taken: the
 * receiver never applies half a frame. After {@link #check}, the frame's cursor is on the first event, so the
 * caller reads {@link #count} events with {@link EventCodec}.
 *
 * @param firstSeq the sequence number of the frame's first event, from 1
 * @param count    how many events the frame carries
 */
public record EventsFrame(long firstSeq, int count) {

    /**
     * Checks a frame a core sent after the handshake: its type, every event's layout, no trailing bytes.
     *
     * @param f the frame; its cursor is left on the first event
     * @return the frame's sequence number and event count
     * @throws ProtocolException when the frame is not EVENTS, an event is malformed, bytes trail, or the sequence
     *                           number is below 1
     */
    public static EventsFrame check(Frame f) throws ProtocolException {
        if (f.type() != MessageType.EVENTS) {
            throw new ProtocolException("a core may only send RUN and EVENTS after the handshake, got " + f.type());
        }
        long firstSeq = f.getLong();
        int count = f.getCount(EventCodec.MIN_EVENT_BYTES);
        int events = f.position();
        for (int i = 0; i < count; i++) {
            EventCodec.skip(f);
        }
        f.expectEnd();
        if (firstSeq < 1) {
            throw new ProtocolException("EVENTS with sequence number " + firstSeq + " (they start at 1)");
        }
        f.rewind(events);
        return new EventsFrame(firstSeq, count);
    }
}

package org.fdnet.event;

import java.util.Objects;

/**
 * A network state event: a Data took a value ({@code datavalue_log}). The value is typed — numbers stay
 * numbers from the runtime's commit to the wire (binary, see {@code docs/protocol.md}) and to a plot; it becomes
 * text only where someone needs text (the logger's COPY, a trace, a table cell).
 *
 * @param sourceId the Data's node id
 * @param time     when the value was committed, µs since the epoch
 * @param value    the value, typed
 */
public record DataValueEvent(int sourceId, long time, TypedValue value) implements NetworkEvent {
    /**
     * Checks the value.
     *
     * @param sourceId the Data's node id
     * @param time     when the value was committed, µs since the epoch
     * @param value    the value, not null
     */
    public DataValueEvent {
        Objects.requireNonNull(value, "value");
    }

    /**
     * The event of a value given in its text form ({@link TypedValue#parse}): for values read back as text (the
     * database's column, a file) and for tests.
     *
     * @param sourceId the Data's node id
     * @param time     when the value was committed, µs since the epoch
     * @param type     the value's type
     * @param text     the value's text form
     * @throws IllegalArgumentException when {@code text} is not a value of {@code type}
     */
    public DataValueEvent(int sourceId, long time, ValueType type, String text) {
        this(sourceId, time, TypedValue.parse(Objects.requireNonNull(type, "type"), Objects.requireNonNull(text, "value")));
    }

    /**
     * The value's type.
     *
     * @return the type of {@link #value()}
     */
    public ValueType type() {
        return value.type();
    }

    /**
     * The same value from another source (the logger maps a core's node ids to global ones).
     *
     * @param newSourceId the id to record it under
     * @return a new event with the same time and value
     */
    public DataValueEvent withSource(int newSourceId) {
        return new DataValueEvent(newSourceId, time, value);
    }
}

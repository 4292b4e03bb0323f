package org.fdnet.event;

import java.util.Objects;

/**
 * A network state event: a Data took a value ({@code datavalue_log}).
 *
 * @param value the value as text: {@code true}, {@code 42}, {@code 0.5}, a string, Base64 for bytes,
 *              comma-separated doubles for postures
 */
public record DataValueEvent(int sourceId, long time, ValueType type, String value) implements NetworkEvent {
    public DataValueEvent {
        Objects.requireNonNull(type, "type");
        Objects.requireNonNull(value, "value");
    }
}

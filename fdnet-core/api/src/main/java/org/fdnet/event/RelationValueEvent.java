package org.fdnet.event;

import java.util.Objects;

/**
 * A Relation's status or value changed ({@code procvalue_log}): e.g. {@code RUNNING},
 * {@code FAILED: java.lang.ArithmeticException: / by zero}, {@code WAITING: missing Arm/Shoulder}.
 *
 * @param sourceId the Relation's node id
 * @param time     when it changed, µs since the epoch
 * @param value    the status or the text the Relation reported
 */
public record RelationValueEvent(int sourceId, long time, String value) implements NetworkEvent {
    /**
     * Checks the value.
     *
     * @param sourceId the Relation's node id
     * @param time     when it changed, µs since the epoch
     * @param value    the status or reported text, not null
     */
    public RelationValueEvent {
        Objects.requireNonNull(value, "value");
    }
}

package org.fdnet.event;

import java.util.Objects;

/**
 * A Relation's status or value changed ({@code procvalue_log}): e.g. {@code RUNNING},
 * {@code FAILED: java.lang.ArithmeticException: / by zero}, {@code WAITING: missing Arm/Shoulder}.
 */
public record RelationValueEvent(int sourceId, long time, String value) implements NetworkEvent {
    public RelationValueEvent {
        Objects.requireNonNull(value, "value");
    }
}

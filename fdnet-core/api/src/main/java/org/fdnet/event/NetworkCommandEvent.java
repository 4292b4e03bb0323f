package org.fdnet.event;

import java.util.Objects;

/**
 * A network command event ({@code netcommand_log}): the structure of the running network changed.
 *
 * @param sourceId   who issued it: a Relation's id for self-organization, 0 for the controller
 * @param time       when the change was made, µs since the epoch
 * @param sourceType {@code proc} for a Relation, {@code controller} for the controller
 * @param command    create, destroy, connect, disconnect, load, unload, hold, resume
 * @param paramsId   what it applies to: a node id, a connection's {@code dataId>relationId}, a module name
 * @param paramsType the kind of that: {@code data}, {@code proc}, {@code reader}, {@code writer}, {@code module}
 */
public record NetworkCommandEvent(int sourceId, long time, String sourceType, NetworkCommand command,
                                  String paramsId, String paramsType) implements NetworkEvent {
    /**
     * Checks the parts.
     *
     * @param sourceId   who issued it, 0 for the controller
     * @param time       when the change was made, µs since the epoch
     * @param sourceType {@code proc} or {@code controller}, not null
     * @param command    what was done, not null
     * @param paramsId   what it applies to, not null
     * @param paramsType the kind of that, not null
     */
    public NetworkCommandEvent {
        Objects.requireNonNull(sourceType, "sourceType");
        Objects.requireNonNull(command, "command");
        Objects.requireNonNull(paramsId, "paramsId");
        Objects.requireNonNull(paramsType, "paramsType");
    }
}

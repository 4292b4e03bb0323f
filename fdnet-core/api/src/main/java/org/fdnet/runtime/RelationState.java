package org.fdnet.runtime;

import java.util.List;
import org.fdnet.netinfo.NodeRef;

/**
 * A Relation's state as the controller reports it.
 *
 * @param relation the Relation whose state this is
 * @param status   running, waiting, held, failed, stopped
 * @param cause    for FAILED: the exception; else {@code null}
 * @param missing  the declared connections' Datas that are not in the running network
 * @param firings  how many times the current instance computed
 */
public record RelationState(NodeRef relation, RelationStatus status, Throwable cause, List<NodeRef> missing,
                            long firings) {
    /**
     * The text of a RelationValueEvent: {@code RUNNING}, {@code FAILED: cause}, {@code WAITING: missing A, B}.
     *
     * @return the status, with the cause or the missing Datas where there are some
     */
    public String text() {
        return switch (status) {
            case FAILED -> "FAILED: " + cause;
            case WAITING -> "WAITING: missing " + String.join(", ", missing.stream().map(NodeRef::toString).toList());
            default -> status.name();
        };
    }
}

package org.fdnet.runtime;

/** Where a Relation instance stands; reported as RelationValueEvents when it changes. */
public enum RelationStatus {
    /** Fires on its inputs and/or period. */
    RUNNING,
    /** Runs, but some Data it is declared to read or write is not in the running network. */
    WAITING,
    /** Its module is on hold: it keeps its state but does not fire. */
    HELD,
    /** An exception stopped it; a parameter change, reload or restart makes a fresh instance. */
    FAILED,
    /** Left the network. */
    STOPPED
}

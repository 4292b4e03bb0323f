package org.fdnet.tls;

import java.util.Locale;

/** What a member of a network may do, as its permissions file grants it by word (see {@link Permissions}). */
public enum Right {
    /** Read a Data's value: a host's {@code read}, the control object's sampled values. Scope: Datas. */
    READ(Scope.NODES),
    /** Change a Data's value: {@code write}, link values delivered into it, {@code send}. Scope: Datas. */
    WRITE(Scope.NODES),
    /** Load a module (deploying a network loads {@code main}). Scope: modules. */
    LOAD(Scope.MODULES),
    /** Unload a module. Scope: modules. */
    UNLOAD(Scope.MODULES),
    /**
     * Change a module's shape or running: create, destroy and connect nodes, open and close links, live edits, hold
     * and resume, parameters; servant messages need it on every module ({@code *}). Scope: modules.
     */
    RESHAPE(Scope.MODULES),
    /** Send events to the network's logger. No scope. */
    RECORD(Scope.NONE);

    /** What a grant of the right names. */
    public enum Scope {
        /** {@code Module/Node} patterns; {@code Module} alone means all its nodes. */
        NODES,
        /** module name patterns. */
        MODULES,
        /** nothing: the right is held or not. */
        NONE
    }

    private final Scope scope;

    Right(Scope scope) {
        this.scope = scope;
    }

    /**
     * What a grant of this right names.
     *
     * @return a Data or module pattern, a module pattern, or nothing
     */
    public Scope scope() {
        return scope;
    }

    /**
     * The word a permissions file uses for this right.
     *
     * @return {@code read}, {@code write}, {@code load}, …
     */
    public String word() {
        return name().toLowerCase(Locale.ROOT);
    }
}

package org.fdnet.netinfo;

/**
 * What changed in a {@link NetworkInfo}, told to its listeners after the change is complete.
 *
 * @param kind    what happened
 * @param module  the module concerned (for a rename: its new name), or {@code null} for the network
 * @param subject the node or connection concerned (for a rename: old name), or {@code null}
 */
public record NetworkChange(Kind kind, String module, String subject) {
    public enum Kind {
        NETWORK_RENAMED(false),
        MODULE_ADDED(false), MODULE_DELETED(true), MODULE_RENAMED(true), MODULE_LOAD_AT_START_CHANGED(false),
        NODE_ADDED(false), NODE_DELETED(true), NODE_RENAMED(true), NODE_CHANGED(false), NODE_REPLACED(true),
        NODES_MERGED(true),
        /** Connection indexes are updated in place for an addition. */
        CONNECTION_ADDED(false),
        CONNECTION_DELETED(true);

        private final boolean movesConnections;

        Kind(boolean movesConnections) {
            this.movesConnections = movesConnections;
        }

        /** Whether connections were removed or re-pointed, so that an index of them is stale. */
        public boolean movesConnections() {
            return movesConnections;
        }
    }
}

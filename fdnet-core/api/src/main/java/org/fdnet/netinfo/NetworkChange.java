package org.fdnet.netinfo;

/**
 * What changed in a {@link NetworkInfo}, told to its listeners after the change is complete.
 *
 * @param kind    what happened
 * @param module  the module concerned (for a rename: its new name), or {@code null} for the network
 * @param subject the node or connection concerned (for a rename: old name), or {@code null}
 */
public record NetworkChange(Kind kind, String module, String subject) {
    /** The kinds of edit, one per {@link NetworkInfo} edit method. */
    public enum Kind {
        /** {@link NetworkInfo#setName}; module and subject are null. */
        NETWORK_RENAMED(false),
        /** {@link NetworkInfo#addModule}. */
        MODULE_ADDED(false),
        /** {@link NetworkInfo#deleteModule}, with the modules inside it. */
        MODULE_DELETED(true),
        /** {@link NetworkInfo#renameModule}: module is the new name, subject the old. */
        MODULE_RENAMED(true),
        /** {@link NetworkInfo#setLoadAtStart}. */
        MODULE_LOAD_AT_START_CHANGED(false),
        /** {@link NetworkInfo#addNode}. */
        NODE_ADDED(false),
        /** {@link NetworkInfo#deleteNode}, with its connections. */
        NODE_DELETED(true),
        /** {@link NetworkInfo#renameNode}: subject is the old name. */
        NODE_RENAMED(true),
        /** {@link NetworkInfo#updateNode} or {@link NetworkInfo#setParameters}. */
        NODE_CHANGED(false),
        /** {@link NetworkInfo#replaceNode}: subject is the node that stays. */
        NODE_REPLACED(true),
        /** {@link NetworkInfo#mergeNodes}: subject is the node that stays. */
        NODES_MERGED(true),
        /** {@link NetworkInfo#addConnection}; connection indexes are updated in place for an addition. */
        CONNECTION_ADDED(false),
        /** {@link NetworkInfo#deleteConnection}. */
        CONNECTION_DELETED(true);

        private final boolean movesConnections;

        Kind(boolean movesConnections) {
            this.movesConnections = movesConnections;
        }

        /**
         * Whether connections were removed or re-pointed, so that an index of them is stale.
         *
         * @return true for edits that remove or redirect connections
         */
        public boolean movesConnections() {
            return movesConnections;
        }
    }
}

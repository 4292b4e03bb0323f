package org.fdnet.logger.store;

/** A core-local node id of one run mapped to its global source id (a row of {@code fdnet_node}). */
public record NodeMapping(int sourceId, int runId, int localId) {
}

package org.fdnet.logger.export;

import org.fdnet.netinfo.NodeKind;

/**
 * A node of a recorded run as the export names it: its global source id, kind, module and name, the host that
 * recorded it and that host's clock offset (µs ahead of the run's coordinator). {@code kind} is null for an id
 * the run never named (e.g. the controller issuing structure changes).
 */
public record RecordedNode(int sourceId, NodeKind kind, String module, String node, String host, long clockOffsetMicros) {
    /** {@code /MODULE/NODE}: the MCAP topic. */
    public String topic() {
        return "/" + module + "/" + node;
    }

    /** {@code MODULE/NODE}, as the viewer and {@code --nodes} name it. */
    public String label() {
        return module + "/" + node;
    }
}

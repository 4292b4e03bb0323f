package org.fdnet.runtime;

import org.fdnet.netinfo.NodeRef;

/** Test access to the Data instance behind a running node (the engine keeps it package-private). */
final class SensorAccess {
    private SensorAccess() {
    }

    static <T extends Data> T sensor(RuntimeNetwork net, NodeRef ref, Class<T> type) {
        return type.cast(net.dataNode(ref).data);
    }
}

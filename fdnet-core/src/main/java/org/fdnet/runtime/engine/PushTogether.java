package org.fdnet.runtime.engine;

import org.fdnet.runtime.Data;
import org.fdnet.runtime.SensorData;
import org.fdnet.runtime.Value;

/** The engine's side of {@link SensorData#pushTogether}: several sensors' values in one commit of their network. */
final class PushTogether {
    private PushTogether() {
    }

    /** Commits {@code values[i]} into {@code ports[i]}; ports not of a running Data are left out. */
    static void commit(Data.DataPort[] ports, Value[] values) {
        DataNode[] nodes = new DataNode[ports.length];
        Dataflow flow = null;
        for (int i = 0; i < ports.length; i++) {
            if (ports[i] instanceof DataNode n && n.alive) {
                if (flow != null && n.flow() != flow) {
                    throw new IllegalArgumentException("pushTogether: " + n.ref + " belongs to another network");
                }
                flow = n.flow();
                nodes[i] = n;
            }
        }
        if (flow != null) {
            flow.commit(null, nodes, values);
        } else {
            java.util.Arrays.fill(values, null);
        }
    }
}

package org.fdnet.runtime.engine;

import org.fdnet.netinfo.NodeRef;

/**
 * A Relation's connections as the engine uses them: the declared Datas in declaration order and the
 * running node behind each ({@code null} while that Data is not in the running network). Immutable;
 * replaced whole when the structure changes, so a firing always uses one consistent wiring.
 */
record Wiring(NodeRef[] inputRefs, DataNode[] inputs, NodeRef[] outputRefs, DataNode[] outputs) {
    static final Wiring EMPTY = new Wiring(new NodeRef[0], new DataNode[0], new NodeRef[0], new DataNode[0]);

    static int indexOf(NodeRef[] refs, String name) {
        for (int i = 0; i < refs.length; i++) {
            if (refs[i].node().equals(name) || refs[i].toString().equals(name)) {
                return i;
            }
        }
        return -1;
    }
}

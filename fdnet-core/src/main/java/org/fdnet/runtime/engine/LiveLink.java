package org.fdnet.runtime.engine;

import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.NodeRef;

/** A connection as the running network makes it: kind and ends (name and flags do not matter here). */
record LiveLink(ConnectionKind kind, NodeRef data, NodeRef relation) {
    static LiveLink of(ConnectionInfo c) {
        return new LiveLink(c.kind(), c.data(), c.relation());
    }
}

package org.fdnet.hi.edit;

import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;

/** Adding and deleting one Reader or Writer; each undoes the other, at the same place in the module's list. */
final class ConnectionEdits {
    private ConnectionEdits() {
    }

    /** {@code position} -1: at the end. */
    static ReversibleEdit add(String module, ConnectionInfo connection, int position) {
        return target -> {
            NetworkInfo network = target.network();
            ModuleInfo m = network.module(module);
            if (position < 0 || m == null) {
                network.addConnection(module, connection);
            } else {
                network.addConnection(module, connection, position);
            }
            return delete(module, connection);
        };
    }

    static ReversibleEdit delete(String module, ConnectionInfo connection) {
        return target -> {
            ModuleInfo m = target.network().module(module);
            int position = m == null ? -1 : m.connections().indexOf(connection);
            target.network().deleteConnection(module, connection);
            return add(module, connection, position);
        };
    }
}

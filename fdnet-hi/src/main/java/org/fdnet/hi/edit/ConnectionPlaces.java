package org.fdnet.hi.edit;

import java.util.ArrayList;
import java.util.List;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * The connections touching some nodes, each with its module and its index in that module's list, taken
 * before an edit moves them: re-adding them in ascending index order puts every one back at its place.
 */
record ConnectionPlaces(List<Place> places) {
    record Place(String module, int index, ConnectionInfo connection) {
    }

    static ConnectionPlaces of(NetworkInfo network, List<NodeRef> nodes) {
        List<Place> places = new ArrayList<>();
        for (ModuleInfo m : network.modules()) {
            List<ConnectionInfo> cs = m.connections();
            for (int i = 0; i < cs.size(); i++) {
                ConnectionInfo c = cs.get(i);
                if (nodes.stream().anyMatch(c::touches)) {
                    places.add(new Place(m.name(), i, c));
                }
            }
        }
        return new ConnectionPlaces(List.copyOf(places));
    }

    /** Edits that add these connections back at their places (run after they are gone). */
    List<ReversibleEdit> restoring() {
        List<ReversibleEdit> edits = new ArrayList<>();
        for (Place p : places) {
            edits.add(ConnectionEdits.add(p.module(), p.connection(), p.index()));
        }
        return edits;
    }

    /** Edits that delete these connections. */
    List<ReversibleEdit> removing() {
        List<ReversibleEdit> edits = new ArrayList<>();
        for (Place p : places) {
            edits.add(ConnectionEdits.delete(p.module(), p.connection()));
        }
        return edits;
    }
}

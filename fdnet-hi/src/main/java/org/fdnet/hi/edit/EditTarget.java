package org.fdnet.hi.edit;

import java.util.Map;
import org.fdnet.layout.ModuleLayout;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.layout.NodeLayout;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * What an edit changes: the network, and the view state keyed by its names. The layout follows renames
 * (a renamed node keeps its place and colour); entries of deleted nodes stay, so that undoing a deletion
 * puts the node back where it was (they are dropped when the .fdg is saved).
 */
public record EditTarget(NetworkInfo network, NetworkLayout layout) {

    void nodeRenamed(NodeRef from, NodeRef to) {
        NodeLayout at = layout.node(from);
        if (at != null) {
            layout.put(to, at);
        }
    }

    void moduleRenamed(String from, String to) {
        ModuleLayout old = layout.module(from);
        if (old == null) {
            return;
        }
        ModuleLayout renamed = layout.moduleOrNew(to);
        renamed.setColour(old.colour());
        renamed.setVisible(old.visible());
        for (Map.Entry<String, NodeLayout> e : old.nodes().entrySet()) {
            renamed.put(e.getKey(), e.getValue());
        }
    }
}

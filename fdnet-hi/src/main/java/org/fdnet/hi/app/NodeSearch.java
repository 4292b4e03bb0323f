package org.fdnet.hi.app;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;

/** Nodes whose name, class, or a parameter's name or value contains the text (ignoring case), in declaration order. */
public final class NodeSearch {
    private NodeSearch() {
    }

    public static List<NodeRef> find(NetworkInfo network, String text) {
        List<NodeRef> hits = new ArrayList<>();
        String needle = text.toLowerCase(Locale.ROOT).trim();
        if (needle.isEmpty()) {
            return hits;
        }
        for (ModuleInfo m : network.modules()) {
            for (NodeInfo n : m.nodes()) {
                if (matches(n, needle)) {
                    hits.add(new NodeRef(m.name(), n.name()));
                }
            }
        }
        return hits;
    }

    private static boolean matches(NodeInfo n, String needle) {
        if (contains(n.name(), needle) || contains(n.className(), needle)) {
            return true;
        }
        for (Parameter p : n.parameters()) {
            if (contains(p.name(), needle) || contains(p.value(), needle)) {
                return true;
            }
        }
        return false;
    }

    private static boolean contains(String s, String needle) {
        return s != null && s.toLowerCase(Locale.ROOT).contains(needle);
    }
}

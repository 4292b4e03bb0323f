package org.fdnet.hi.app;

import java.awt.Font;
import java.util.ArrayList;
import java.util.List;
import javax.swing.UIManager;
import org.fdnet.hi.graph.Java2DSketch;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.viewer.legible.LegibleFont;

/**
 * The editor's fonts for a network's names (the network's, its modules' and its nodes'): one for the graph
 * and, when the look and feel's default font cannot draw them, one for the text fields, lists and trees too.
 */
final class NamesFont {
    private NamesFont() {
    }

    /** Every name the editor shows for {@code network}. */
    static List<String> of(NetworkInfo network) {
        List<String> names = new ArrayList<>();
        names.add(network.name());
        for (ModuleInfo m : network.modules()) {
            names.add(m.name());
            for (NodeInfo n : m.nodes()) {
                names.add(n.name());
            }
        }
        return names;
    }

    /** The graph's font for {@code network}'s names (the warning says when none is installed). */
    static LegibleFont.Choice forGraph(NetworkInfo network) {
        return LegibleFont.forNames(Java2DSketch.PLAIN, of(network));
    }

    /**
     * Makes the look and feel's default font one that draws {@code network}'s names if it does not; true when
     * it changed (the caller updates its components' UI).
     */
    static boolean fitSwingDefault(NetworkInfo network) {
        Font current = UIManager.getFont("defaultFont");
        if (current == null) {
            current = UIManager.getFont("Label.font");
        }
        if (current == null) {
            return false;
        }
        LegibleFont.Choice c = LegibleFont.forNames(current, of(network));
        if (!c.legible() || c.font() == current) {
            return false;
        }
        UIManager.put("defaultFont", c.font());
        return true;
    }
}

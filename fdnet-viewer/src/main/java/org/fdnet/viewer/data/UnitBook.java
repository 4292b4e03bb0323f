package org.fdnet.viewer.data;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * The units the viewer was told (the logger knows none): from {@code --nodes Name[unit]} and from the plots of a
 * layout. A component may have a unit of its own ({@code Course/track[2]} in rad while {@code Course/track} is in
 * m); otherwise it has its node's.
 */
public final class UnitBook {
    private final Map<String, String> units = new ConcurrentHashMap<>();

    /** Remembers the selection's unit (an empty unit is not remembered). */
    public void learn(NodeSelection selection) {
        if (!selection.unit().isEmpty()) {
            units.put(selection.name(), selection.unit());
        }
    }

    /** The unit of a series name ({@code Module/Node} or {@code Module/Node[i]}), or {@code fallback}. */
    public String unitOf(String seriesName, String fallback) {
        String exact = units.get(seriesName);
        if (exact != null) {
            return exact;
        }
        int open = seriesName.lastIndexOf('[');
        if (open > 0 && seriesName.endsWith("]")) {
            String node = units.get(seriesName.substring(0, open));
            if (node != null) {
                return node;
            }
        }
        return fallback;
    }
}

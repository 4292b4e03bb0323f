package org.fdnet.viewer.data;

/**
 * A node the user asked to plot: {@code Module/Node} or {@code Node} (any module), optionally followed by
 * its unit in brackets: {@code Balance/stability margin[m]}. The logger knows no units, so the unit comes
 * from here.
 */
public record NodeSelection(String name, String unit) {

    public static NodeSelection parse(String text) {
        String t = text.trim();
        if (t.isEmpty()) {
            throw new IllegalArgumentException("an empty node name");
        }
        int open = t.lastIndexOf('[');
        if (t.endsWith("]") && open > 0) {
            return new NodeSelection(t.substring(0, open).trim(), t.substring(open + 1, t.length() - 1).trim());
        }
        return new NodeSelection(t, "");
    }

    @Override
    public String toString() {
        return unit.isEmpty() ? name : name + "[" + unit + "]";
    }
}

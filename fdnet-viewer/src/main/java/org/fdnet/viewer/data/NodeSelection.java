package org.fdnet.viewer.data;

/**
 * A node the user asked to plot: {@code Module/Node} or {@code Node} (any module), optionally followed by
 * its unit in brackets: {@code Balance/stability margin[m]}. One component of a Data holding several numbers
 * is named by its index: {@code Course/track[0]}, with a unit {@code Course/track[0][m]} (brackets holding only
 * digits are an index, never a unit). The logger knows no units, so the unit comes from here.
 */
public record NodeSelection(String name, String unit) {

    public static NodeSelection parse(String text) {
        String t = text.trim();
        if (t.isEmpty()) {
            throw new IllegalArgumentException("an empty node name");
        }
        int open = t.lastIndexOf('[');
        if (t.endsWith("]") && open > 0) {
            String inside = t.substring(open + 1, t.length() - 1).trim();
            if (!inside.chars().allMatch(Character::isDigit) || inside.isEmpty()) {
                return new NodeSelection(t.substring(0, open).trim(), inside);
            }
        }
        return new NodeSelection(t, "");
    }

    /** The node's name without a component index ({@code Course/track} for {@code Course/track[0]}). */
    public String node() {
        int open = name.lastIndexOf('[');
        return open > 0 && name.endsWith("]") ? name.substring(0, open) : name;
    }

    /** True when the series belongs to this selection: the node's series, or the one component named. */
    public boolean matches(Series series) {
        String n = series.name();
        return n.equals(name) || !name.endsWith("]") && n.startsWith(name + "[") && n.endsWith("]");
    }

    @Override
    public String toString() {
        return unit.isEmpty() ? name : name + "[" + unit + "]";
    }
}

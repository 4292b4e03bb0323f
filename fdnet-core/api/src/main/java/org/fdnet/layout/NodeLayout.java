package org.fdnet.layout;

/**
 * Where and how the editor draws one node. Sizes and colour are optional ({@code null}: the editor's
 * default for the node's kind).
 *
 * @param x      the node's left edge in the editor's model coordinates
 * @param y      the node's top edge in the editor's model coordinates
 * @param width  its width, or null for the default
 * @param height its height, or null for the default
 * @param colour {@code #RRGGBB}, or null for the default
 */
public record NodeLayout(double x, double y, Double width, Double height, String colour) {
    /**
     * Checks the layout.
     *
     * @param x      the left edge, finite
     * @param y      the top edge, finite
     * @param width  the width, above 0, or null
     * @param height the height, above 0, or null
     * @param colour {@code #RRGGBB}, or null
     * @throws IllegalArgumentException when a coordinate is not finite, a size not positive or the colour malformed
     */
    public NodeLayout {
        if (!Double.isFinite(x) || !Double.isFinite(y)) {
            throw new IllegalArgumentException("position (" + x + ", " + y + ") is not finite");
        }
        if (width != null && !(width > 0) || height != null && !(height > 0)) {
            throw new IllegalArgumentException("size " + width + " x " + height + " must be positive");
        }
        Colour.check(colour);
    }

    /**
     * A node at a position, of the default size and colour.
     *
     * @param x the left edge
     * @param y the top edge
     * @return a layout whose width, height and colour are null
     */
    public static NodeLayout at(double x, double y) {
        return new NodeLayout(x, y, null, null, null);
    }
}

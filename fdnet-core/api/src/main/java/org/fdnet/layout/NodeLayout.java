package org.fdnet.layout;

/**
 * Where and how the editor draws one node. Sizes and colour are optional ({@code null}: the editor's
 * default for the node's kind).
 */
public record NodeLayout(double x, double y, Double width, Double height, String colour) {
    public NodeLayout {
        if (!Double.isFinite(x) || !Double.isFinite(y)) {
            throw new IllegalArgumentException("position (" + x + ", " + y + ") is not finite");
        }
        if (width != null && !(width > 0) || height != null && !(height > 0)) {
            throw new IllegalArgumentException("size " + width + " x " + height + " must be positive");
        }
        Colour.check(colour);
    }

    public static NodeLayout at(double x, double y) {
        return new NodeLayout(x, y, null, null, null);
    }
}

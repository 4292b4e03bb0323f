/**
 * The graphic panel: one component ({@link org.fdnet.hi.graph.GraphCanvas}) paints the whole network, so a
 * thousand nodes stay fluid. {@link org.fdnet.hi.graph.GraphScene} is what is shown (places and sizes from
 * the .fdg, visible modules, selection, highlighted relatives); {@link org.fdnet.hi.graph.GraphPainter}
 * draws it on a {@link org.fdnet.hi.graph.Sketch}, which is the screen, a PNG or an SVG file alike. While the
 * selection is dragged, the canvas keeps a {@link org.fdnet.hi.graph.DragBackdrop} of everything else and each frame
 * paints only the selection and its connections over it.
 *
 * <pre>
 *  NetworkInfo ──changes──▶ GraphScene ◀── NetworkLayout (.fdg: x, y, size, colour, visible)
 *                               │  ▲ mouse: select, drag, rubber band (view state only)
 *                               ▼  │
 *                         GraphPainter ──▶ Sketch ──┬─ Java2DSketch ─▶ GraphCanvas / PNG
 *                                                   └─ SvgSketch ────▶ .svg
 * </pre>
 */
package org.fdnet.hi.graph;

/**
 * Java2D drawing of the simulated RoQ for windows, screenshots and documentation.
 *
 * <pre>
 *  RoqSimulator.read ──▶ SensorSnapshot ─┐
 *  Heightfield (terrain, fragile cells) ─┼──▶ RoqPainter.paint(Graphics2D, snapshot, terrain, bounds)
 *                                        │        top view: terrain shading, cells, body, legs, feet, CoM
 *                                        │        side view: terrain profile under the body, body, legs
 *                                        └──────  panel: time, inclinometer, sole forces, ranges, depth image
 * </pre>
 *
 * The painter keeps no reference to the simulator and allocates nothing per frame but Java2D's shapes; a Swing
 * component calls it from {@code paintComponent}, {@link org.fdnet.roq.view.RoqScreenshot} into a PNG.
 */
package org.fdnet.roq.view;

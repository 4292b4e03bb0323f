/**
 * Java2D drawing of the simulated RoQ for windows, screenshots and documentation.
 *
 * <pre>
 *  RoqSimulator.read ──▶ SensorSnapshot ─┐
 *  Heightfield (terrain, fragile cells) ─┼──▶ RoqPainter.paint(Graphics2D, snapshot, terrain, bounds)
 *                                        │        top view: terrain shading, cells, body, legs, feet, CoM,
 *                                        │                  support polygon of the feet in contact, path so far
 *                                        │        side view: terrain profile under the body, body, legs
 *                                        └──────  panel: time, inclinometer, sole forces, ranges, depth image
 * </pre>
 *
 * The painter keeps no reference to the simulator and allocates nothing per frame but Java2D's shapes; a Swing
 * component calls it from {@code paintComponent}, {@link org.fdnet.roq.view.RoqScreenshot} into a PNG.
 *
 * <p>The {@code fdnet demo --gui} window:
 * <pre>
 *  fdnet demo (every 100 ms) ──▶ snapshot copy + DemoFigures ──invokeLater──▶ RoqDemoPanel.show
 *                                                                              ├─ view: RoqPainter + path
 *                                                                              └─ live figures (labels)
 *  RoqDemoWindow = FlatLaf JFrame around the panel;  --screenshot: RoqDemoPanel.writePng (window or off-screen)
 * </pre>
 */
package org.fdnet.roq.view;

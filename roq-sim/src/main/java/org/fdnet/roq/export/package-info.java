/**
 * RoQ in 3D in an exported recording: Foxglove's well-known schemas derived from a RoQ run's recorded Datas, plugged
 * into the logger's MCAP export as a {@link org.fdnet.logger.export.SceneSource} (listed in META-INF/services).
 *
 * <pre>
 *  export rows (time order) ──▶ RoqScene: latest main/body position, attitude, joint angles, foot forces, Course/heading
 *     ├─▶ /roq/tf      foxglove.FrameTransform  world → body (position, roll, pitch, heading)
 *     ├─▶ /roq/robot   foxglove.SceneUpdate     body box, legs (RoqGeometry.legInBody), feet, sole-force arrows
 *     └─▶ /roq/course  foxglove.SceneUpdate     fragile cells (the course's), broken ones (FragileCell's rule on the recorded feet)
 * </pre>
 *
 * The database does not record the course: it comes from the export's {@code --scene course=NAME|FILE} option, and
 * without it no cells are drawn.
 */
package org.fdnet.roq.export;

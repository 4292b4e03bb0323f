/**
 * The bridge between a running FDNet network and RoQ's simulator.
 *
 * <pre>
 *   stepped (one thread):  sim.step(n) ─▶ read snapshot ─▶ RoqSensor.push … ─▶ network.advanceTo(t) ─▶ send(JointTargets)
 *                              ▲                                                                          │
 *                              └──────────────────────────────── next cycle ◀─────────────────────────────┘
 *   real time: 1 kHz loop thread ─▶ snapshot (seqlock) ◀─poll─ roq-bridge thread ─▶ network (wall clock) ─▶ command slot
 * </pre>
 *
 * <p>{@link org.fdnet.roq.bridge.CourseMeter} measures a run on a course by ground truth (for the demo's summary and
 * the robot test kit's measures): track and heading error and, through
 * {@link org.fdnet.roq.bridge.BreakthroughCauses} (fed the feet's positions and the gait phase every sample), the
 * cells broken under a probing foot while it pressed apart from the loaded-foot breakthroughs — every other break,
 * under a standing foot during another foot's press too — and whether each breakthrough was under the swinging foot or
 * a standing one, and whether that standing foot had slid since it was set down. No controller reads any of them.
 */
package org.fdnet.roq.bridge;

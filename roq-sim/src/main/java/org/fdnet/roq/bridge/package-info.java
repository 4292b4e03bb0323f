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
 * <p>{@link org.fdnet.roq.bridge.CourseRun} measures one stepped run by ground truth (distance, drift off the course
 * line and heading, tilt, fall, broken cells) for the suites and {@code bench roq --part heading}; no controller
 * reads it.
 */
package org.fdnet.roq.bridge;

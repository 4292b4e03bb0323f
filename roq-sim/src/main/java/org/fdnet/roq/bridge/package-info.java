/**
 * The bridge between a running FDNet network and RoQ's simulator.
 *
 * <pre>
 *   stepped (one thread):  sim.step(n) ─▶ read snapshot ─▶ RoqSensor.push … ─▶ network.advanceTo(t) ─▶ send(JointTargets)
 *                              ▲                                                                          │
 *                              └──────────────────────────────── next cycle ◀─────────────────────────────┘
 *   real time: 1 kHz loop thread ─▶ snapshot (seqlock) ◀─poll─ roq-bridge thread ─▶ network (wall clock) ─▶ command slot
 * </pre>
 */
package org.fdnet.roq.bridge;

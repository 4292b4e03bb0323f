/**
 * RoQ's nodes, usable by {@code class} in a {@code .fdn}: a {@link org.fdnet.roq.node.RoqSensor} for each
 * sensor (parameter {@code channel}), {@link org.fdnet.roq.node.JointTargets} for the servos, and the
 * Relations of the motion network (stand, crawl gait, keep balance, probe the ground, posture integration,
 * inverse kinematics, fall detection, the tilt reflex).
 *
 * <pre>
 *   simulator snapshot ──SimBridge──▶ RoqSensor Datas (attitude, joint angles, foot forces…)
 *                                          │ read by
 *   StandPosture ──▶ feet (12, body frame) ─┼──▶ LegInverseKinematics ──▶ JointTargets ──SimBridge──▶ command slot
 *                                          └──▶ FallDetector ──▶ fallen (boolean)
 *
 *   probing (roq-rubble): CrawlGait ──gait phase {leg, in air, attempt}──▶ ProbeGround ◀── foot forces
 *                             ▲                                              │
 *                             └────────── probe verdict {leg, ±1, attempt} ──┤
 *                                         probe press (12) ──▶ PostureIntegration
 *
 *   tilt reflex (no period, fires on every snapshot):
 *   attitude, imu gyro, gait feet, gait phase ──▶ TiltReflex ──reflex press (12)──▶ PostureIntegration ──▶ IK
 * </pre>
 */
package org.fdnet.roq.node;

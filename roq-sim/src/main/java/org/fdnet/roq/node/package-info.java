/**
 * RoQ's nodes, usable by {@code class} in a {@code .fdn}: a {@link org.fdnet.roq.node.RoqSensor} for each
 * sensor (parameter {@code channel}), {@link org.fdnet.roq.node.JointTargets} for the servos, and the
 * Relations of the motion network (stand, crawl gait, keep balance, hold course, probe the ground, level the body,
 * posture integration, inverse kinematics, fall detection, the tilt reflex). Relations act on what a real RoQ senses,
 * never on ground truth ({@code body_position}, {@code centre_of_mass}: for measurement and tests only);
 * {@link org.fdnet.roq.node.SensedFeet} turns joint angles, sole forces and attitude into feet and centre of
 * pressure for the closed loops; {@link org.fdnet.roq.node.GaitPhase} and {@link org.fdnet.roq.node.Feet} are the
 * typed views of the gait phase and of the twelve feet numbers; {@link org.fdnet.roq.node.LegReach} is where a leg
 * reaches and what it carries, by the model, for a gait that plans within it ({@link
 * org.fdnet.roq.node.PlanarConstraints}: the nearest point within ranked half-planes).
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
 *   closed loops (every 10 ms):
 *   gait phase, joint angles, foot forces, attitude ──▶ KeepBalance ──balance shift (12)──▶ PostureIntegration
 *   imu gyro, attitude, joint angles, foot forces, gait phase ──▶ HoldCourse ──steer (rad per stance)──▶ CrawlGait
 *   attitude, gait feet ──▶ LevelBody ──level (12, z only: the body back to level on a slope)──▶ PostureIntegration
 *
 *   weight-transfer crawl (roq-transfer, every 10 ms):
 *   foot forces, joint angles, attitude, sole targets, steer ──▶ TransferCrawl ──gait feet, gait phase (GaitPhase)──┐
 *   gait phase, joint angles, foot forces, attitude ──▶ DistributeForces ──sole targets (4 N)──▶ TrackSoleForces   │
 *   TrackSoleForces ──sole admittance (12, z only)──▶ PostureIntegration ◀─────────────────────────────────────────┘
 *
 *   tilt reflex (no period, fires on every snapshot):
 *   attitude, imu gyro, gait feet, gait phase ──▶ TiltReflex ──reflex press (12)──▶ PostureIntegration ──▶ IK
 * </pre>
 */
package org.fdnet.roq.node;

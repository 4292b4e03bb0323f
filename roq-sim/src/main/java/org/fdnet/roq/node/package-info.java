/**
 * RoQ's nodes, usable by {@code class} in a {@code .fdn}: a {@link org.fdnet.roq.node.RoqSensor} for each
 * sensor (parameter {@code channel}), {@link org.fdnet.roq.node.JointTargets} for the servos, and the
 * Relations of the motion network (stand, inverse kinematics, fall detection).
 *
 * <pre>
 *   simulator snapshot ──SimBridge──▶ RoqSensor Datas (attitude, joint angles, foot forces…)
 *                                          │ read by
 *   StandPosture ──▶ feet (12, body frame) ─┼──▶ LegInverseKinematics ──▶ JointTargets ──SimBridge──▶ command slot
 *                                          └──▶ FallDetector ──▶ fallen (boolean)
 * </pre>
 */
package org.fdnet.roq.node;

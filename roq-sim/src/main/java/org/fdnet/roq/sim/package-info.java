/**
 * The simulated RoQ (a TITAN-VIII quadruped on MuJoCo 2.2.2) and its C joint loop, reached through JNI.
 *
 * <pre>
 *  Course ──CourseLoader── file          RoqGeometry (every figure) ──▶ MjcfWriter ──▶ MJCF ─┐
 *  Course ──▶ Heightfield ─────────────────────────────────────────────────────────────────▶ RoqNative.open
 *
 *              Java                            one direct buffer (SharedBlockLayout)          C (libroqsim.so)
 *  JointCommand ──send()──▶ command slot (sequenced) ─────────────────▶ tick: read slot, validate, count bad
 *                                                                        12 servos: PD → motor limits → torque
 *                                                                        mj_step (MuJoCo)
 *  Stimulus ──stimulate()──▶ stimulus table (sequenced) ──────────────▶ pushes → xfrc_applied; cell breaks
 *  SensorSnapshot ◀─read()── snapshot + LoopStatistics (seqlock) ◀────── sensors: joints, inclinometer, IMU, soles,
 *                                                                        IR, ultrasonic, depth pixels, fragile cells
 *  appliedCommands() ◀──── applied-command ring (applied tick, source tick per command, same seqlock)
 * </pre>
 *
 * In {@link org.fdnet.roq.sim.SimMode#REAL_TIME} the tick runs on a C thread at 1 kHz on absolute deadlines; in
 * {@link org.fdnet.roq.sim.SimMode#STEPPED} the same tick runs {@code n} times per
 * {@link org.fdnet.roq.sim.RoqSimulator#step(int)}. Java never calls into C per tick: it reads and writes the
 * buffer. {@link org.fdnet.roq.sim.RoqNativeLibrary} loads the library and checks the ABI handshake: version, size,
 * then {@link org.fdnet.roq.sim.LayoutHandshake} compares the C side's one layout table ({@code ROQ_LAYOUT} in
 * roq_layout.h) by name with every constant of {@link org.fdnet.roq.sim.SharedBlockLayout} and
 * {@code NativeParameters}. On the C side a constant {@code roq_model}, a {@code roq_state} and the real-time
 * thread's {@code roq_rt} are apart, as MuJoCo's {@code mjModel} and {@code mjData} (docs/explanation/roq-sim.md).
 */
package org.fdnet.roq.sim;

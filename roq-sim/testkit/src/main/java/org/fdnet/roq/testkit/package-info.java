/**
 * The robot-level test kit: JUnit 5 tests of a network driving the simulated RoQ, stepped and deterministic.
 *
 * <pre>
 *   @RoqTest class ─▶ RoqExtension ─▶ @Roq(network, course, noise) SimulatedRoq parameter
 *     SimulatedRoq: RoqSimulator (MuJoCo, stepped, seeded noise or none) ◀─ SimBridge ─▶ TestNetwork (driven clock)
 *       each 10 ms step: hooks ─▶ plant + network in lockstep ─▶ ground truth sampled (CourseMeter)
 *       measures() / assertThat() ─▶ RoqMeasures: distance, track, heading, tilt, fall, breakthroughs, margin
 *     test fails ─▶ FailureEvidence: PNG of the robot view + the run's events into a logger database
 *                   ─▶ the failure message names both and the replay command
 * </pre>
 *
 * <p>Courses are named as {@link org.fdnet.roq.testkit.CourseSpec} reads them. The same test gives the same
 * robot and the same network events: {@link org.fdnet.roq.testkit.SimulatedRoq#stateHash()} and
 * {@link org.fdnet.roq.testkit.SimulatedRoq#eventLogHash()} are the proof. Each test has its own simulator, so
 * tests may run in parallel (one simulator per thread).
 */
package org.fdnet.roq.testkit;

/**
 * The network-level test kit: JUnit 5 tests of networks and node classes on a driven clock.
 *
 * <pre>
 *   @FdnetTest class ─▶ FdnetExtension ─▶ @NetworkFile("x.fdn") TestNetwork parameter
 *        TestNetwork: RuntimeNetwork on a DrivenClock ─▶ every event kept in a MemoryEventSink
 *          set/send ─▶ Data ─▶ Relations fire on the test's thread ─▶ value/history/assertValue
 *          advance/await ─▶ periods fall due in simulated time (no wall-clock sleep anywhere)
 * </pre>
 *
 * <p>A test is deterministic: the same network fed the same way gives the same values and time stamps. Nothing here
 * starts CORBA or a database; the robot-level kit ({@code org.fdnet.roq.testkit}, artifact roq-testkit) builds on
 * {@link org.fdnet.testkit.TestNetwork} to run a network beside the simulated RoQ.
 */
package org.fdnet.testkit;

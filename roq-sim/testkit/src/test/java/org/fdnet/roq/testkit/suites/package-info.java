/**
 * The project's own robot suites, written on the robot test kit as a user's suites are: each test names a network of
 * {@code networks/}, a course and a sensor-noise seed, gets a {@link org.fdnet.roq.testkit.SimulatedRoq} (the stepped
 * MuJoCo plant under the network on a driven clock), runs it in simulated time and asserts on its measures, its
 * sensor snapshot and the network's values. Independent runs go two at a time, one simulated robot per thread.
 */
package org.fdnet.roq.testkit.suites;

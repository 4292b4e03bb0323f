/**
 * roq-sim's commands under {@code fdnet}: {@code sim} (run a course, print progress and a summary, optionally
 * a screenshot) and {@code demo} (RoQ walking under a network on the real-time simulator, recorded by an
 * {@code InProcessLogger} of the user's database). Registered through
 * {@link org.fdnet.roq.cli.RoqCommandProvider} in {@code META-INF/services/org.fdnet.cli.spi.CommandProvider}.
 *
 * <p>The benchmarks of the same package live in roq-sim/bench, registered there by {@code RoqBenchmarks}:
 * {@code bench rt} (the joint loop's wake-up latency beside cyclictest), {@code bench sim} (the stepped tick beside
 * a bare {@code mj_step} loop), {@code bench roq} ((a) stepped speed of a network driving the plant; (b)
 * {@code ReflexLatencyBench}: stimulus-to-applied-command latency through the network, {@code StimulusLatencyRun}
 * per run; {@code --part push}: {@code PushSurvivalBench}, the largest push survived with and without Balance and
 * Reflex, by bisection over stepped {@code PushTrial}s; {@code --part heading}: {@code HeadingDriftBench}, drift
 * off the course line with and without module Course, means over noise seeds; {@code --part breakthroughs}:
 * {@code BreakthroughSweep}, cells broken under a loaded foot summed over noise seeds, with and without module
 * Probing; {@code NoiseSeeds} reads their {@code --noise}).
 *
 * <pre>
 *   fdnet demo ──▶ DemoCommand ──▶ InProcessLogger? ─▶ RuntimeNetwork + RoqSimulator (real time) + SimBridge
 *                                  └─▶ DemoMeter (what the network itself reports) ─▶ progress lines, summary
 * </pre>
 */
package org.fdnet.roq.cli;

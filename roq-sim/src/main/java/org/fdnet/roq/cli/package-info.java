/**
 * roq-sim's commands under {@code fdnet}: {@code sim} (run a course, print progress and a summary, optionally
 * a screenshot) and the benchmarks {@code bench rt} (the joint loop's wake-up latency beside cyclictest) and
 * {@code bench sim} (the stepped tick beside a bare {@code mj_step} loop), {@code bench roq} ((a) stepped speed of a
 * network driving the plant; (b) {@link org.fdnet.roq.cli.ReflexLatencyBench}: stimulus-to-applied-command latency
 * through the network, {@link org.fdnet.roq.cli.StimulusLatencyRun} per run; {@code --part push}:
 * {@link org.fdnet.roq.cli.PushSurvivalBench}, the largest push survived with and without Balance and Reflex, by
 * bisection over stepped {@link org.fdnet.roq.cli.PushTrial}s; {@code --part heading}:
 * {@link org.fdnet.roq.cli.HeadingDriftBench}, drift off the course line with and without module Course) and
 * {@code demo}. Registered through
 * {@link org.fdnet.roq.cli.RoqCommandProvider} in {@code META-INF/services/org.fdnet.cli.CommandProvider}.
 */
package org.fdnet.roq.cli;

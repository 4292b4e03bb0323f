/**
 * {@code fdnet soak}: a distributed network with the logger, run for a while under a schedule of faults, then counted.
 *
 * <pre>
 *   SoakCommand ── SoakCluster: embedded PostgreSQL (this JVM) ◀── fdnet logger ◀── every host's logger client
 *        │                      fdnet naming, fdnet host flyer / crawler (--link-faults), fdnet run (operator)
 *        ├─ SequenceWriter: "send main/Seq=k" on the run's standard input, 20 a second; "ok" = applied on the flyer
 *        │       Seq (flyer) ══link══▶ stand-in Seq (crawler) ─ Relay ─▶ Echo (crawler) ══link══▶ stand-in Echo (operator)
 *        ├─ FaultPlan: link faults, kill -9 a host, kill -9 the logger, PostgreSQL stopped 10 s, naming restarted;
 *        │             with --apart, cycles of network faults on the rig's links (FaultInjector → ApartRig)
 *        ├─ DeliveryWatch: polls the database — when did a value acknowledged after a fault reach it end to end
 *        ├─ OutputWatch: every process's lines, timed — "host H LOST", "is back", each host's health line
 *        ├─ NetworkFaultCheck: per network fault, detection, re-wiring, longest call, Relation stall, memory held
 *        └─ SequenceCount: per node, by name and the soak's time window, what the database holds against what was applied
 * </pre>
 *
 * With {@code --apart} ({@link org.fdnet.logger.soak.SoakPlacement}) each process runs on a host of its own, a network
 * namespace of an {@link org.fdnet.apart.ApartRig}: naming, flyer, crawler, logger (reaching this JVM's PostgreSQL
 * through socat to its Unix socket) and operator (the run).
 *
 * A value is recorded by its Data's home host (stand-ins do not record values), so each value of {@code Seq} and
 * {@code Echo} must be stored exactly once. Anything else is an anomaly; anomalies of values acknowledged around a host's
 * {@code kill -9} are what such a kill may cost (its unacknowledged logger events, its in-flight link values), every
 * other one fails the soak.
 */
package org.fdnet.logger.soak;

/**
 * {@code fdnet bench corba} and the node classes it places on other hosts ({@link org.fdnet.corba.bench.HopStamp},
 * built in on every host).
 *
 * <pre>
 *   CorbaBenchmark ──▶ BenchTopology: naming + bench-a, bench-probe (this JVM), bench-b (child JVM, fdnet host)
 *        │
 *        ├─ HopSampler: bare Host.ping() (baseline) │ write ping on bench-a ──▶ HopStamp on bench-b ──▶ hop back
 *        │              on bench-a: round trip, one-way; back to back and one value every 1 / 10 / 100 ms
 *        ├─ CpuClock: CPU of this JVM and bench-b's JVM over each idle-gap phase (what the idle watch costs)
 *        └─ sustained: seq on bench-a ──▶ bench-b ──▶ bench-probe ──▶ ArrivalCount (each arrival counted,
 *                      per 10 s window)                                ──▶ table of figures and verdicts
 * </pre>
 */
package org.fdnet.corba.bench;

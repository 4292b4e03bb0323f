/**
 * {@code fdnet bench load}, the network generator it shares with the property tests, and the one way a
 * benchmark measures a fresh JVM ({@link org.fdnet.bench.FreshJvmRun}, on {@link org.fdnet.corba.FdnetChildProcess}).
 *
 * <pre>
 *   NetworkGenerator(seed) ──▶ NetworkInfo ──save──▶ temp .fdn
 *   cold:  FreshJvmRun ──▶ child JVM: fdnet bench load cold-probe FILE (ColdLoadProbe: load + validate, first
 *          descendants query; or --bare SAX parse) ──▶ its own timings; whole-process fdnet validate, fdnet --version
 *   warm:  LoadBenchmark: bare SAX parse (baseline) vs NetworkRepository.load; BFS over int arrays (baseline)
 *          vs NetworkInfo.descendants ──▶ first / median / best
 *   ──▶ ratios, target verdicts on the cold figures and the warm medians
 * </pre>
 *
 * The other parts' benchmarks live beside their code ({@code runtime.bench}, {@code corba.bench},
 * {@code logger.cli}); all of them print a baseline measured in the same run.
 */
package org.fdnet.bench;

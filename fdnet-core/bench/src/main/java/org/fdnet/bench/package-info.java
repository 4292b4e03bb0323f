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
 * This package is fdnet-core/bench's, a module of its own: no product jar carries a benchmark. {@link
 * org.fdnet.bench.CoreBenchmarks} registers {@code load}, {@code core} ({@code runtime.bench}) and {@code corba}
 * ({@code corba.bench}) through {@code CommandProvider}; the other bench modules (fdnet-logger/bench, ...) register
 * theirs the same way. All of them print a baseline measured in the same run.
 */
package org.fdnet.bench;

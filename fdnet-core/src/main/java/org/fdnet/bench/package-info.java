/**
 * {@code fdnet bench load} and the network generator it shares with the property tests.
 *
 * <pre>
 *   NetworkGenerator(seed) ──▶ NetworkInfo ──save──▶ temp .fdn
 *   LoadBenchmark: bare SAX parse (baseline) vs NetworkRepository.load; BFS over int arrays (baseline)
 *                  vs NetworkInfo.descendants ──▶ first / median / best, ratios, target verdicts
 * </pre>
 *
 * The other parts' benchmarks live beside their code ({@code runtime.bench}, {@code corba.bench},
 * {@code logger.cli}); all of them print a baseline measured in the same run.
 */
package org.fdnet.bench;

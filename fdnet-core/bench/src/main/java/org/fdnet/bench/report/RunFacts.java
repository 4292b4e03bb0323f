package org.fdnet.bench.report;

/**
 * Where and when a benchmark ran, as the table shows it.
 *
 * @param date    the day, ISO (e.g. 2026-11-28)
 * @param commit  the project's commit, abbreviated (with {@code +changes} when the work tree differs from it)
 * @param machine cores, memory and JDK, e.g. {@code 2 cores, 24 GiB, JDK 17.0.15}
 * @param load    the 1-minute load average when the benchmark started and when it ended, e.g. {@code 0.12 → 0.85}
 */
record RunFacts(String date, String commit, String machine, String load) {
}

/**
 * The {@code fdnet} command line (picocli), the entry point of {@code bin/fdnet}. The plug-in point,
 * {@link org.fdnet.cli.spi.CommandProvider}, is in fdnet-api (package org.fdnet.cli.spi), so the logger and the viewer add their
 * commands without depending on the engine.
 *
 * <pre>
 *   bin/fdnet ──▶ FdnetCommand.main ──▶ core commands (validate, info [--params: ParameterListing], fmt, keys)
 *                        ├── sdk install ──▶ MavenRun(mvn -B install in fdnet.home) ──▶ InstallProgress: a line per module
 *                        ├── new nodes DIR ──▶ MavenRun(mvn -B -o archetype:generate, FDNet's archetype) ──▶ DIR
 *                        │
 *                        ├── ServiceLoader&lt;CommandProvider&gt; ──▶ commands of every module (run, host, logger, demo, ...)
 *                        └── bench (BenchCommand names none) ──▶ benchmarks of every bench module
 *                              (fdnet-core/bench: load, core, corba; fdnet-logger/bench: logger; ...: viewer, hi, rt, sim, roq)
 * </pre>
 */
package org.fdnet.cli;

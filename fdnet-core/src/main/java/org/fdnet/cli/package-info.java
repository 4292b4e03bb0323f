/**
 * The {@code fdnet} command line (picocli), the entry point of {@code bin/fdnet}.
 *
 * <pre>
 *   bin/fdnet ──▶ FdnetCommand.main ──▶ core commands (validate, info, fmt)
 *                        │
 *                        ├── ServiceLoader&lt;CommandProvider&gt; ──▶ commands of other parts (run, logger, host, ...)
 *                        └── bench ──▶ benchmarks from every CommandProvider (load, core, corba, logger)
 * </pre>
 */
package org.fdnet.cli;

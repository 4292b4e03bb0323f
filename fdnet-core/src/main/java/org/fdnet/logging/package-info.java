/**
 * Where log lines go when FDNet runs as the {@code fdnet} command: the terminal shows the command's own
 * lines and warnings only; everything at INFO (PostgreSQL's start-up, JacORB, FDNet's own details) goes to
 * one log file, named on the terminal once, when its first line is written.
 *
 * <pre>
 *   LoggerFactory.getLogger(..) ──▶ RoutedLogger ──▶ LogRouting
 *                                                     ├─ WARN, ERROR ─────────▶ stderr ("fdnet: WARN ...")
 *                                                     └─ INFO and above ──────▶ ~/.fdnet/logs/fdnet-*.log
 * </pre>
 *
 * Before a command's log file is created, {@link org.fdnet.logging.OldLogFiles} deletes the folder's oldest
 * {@code fdnet-*.log} files so that the newest 20 remain ({@code fdnet.logFilesKept}).
 *
 * {@link org.fdnet.logging.QuietTerminalLogging#select()} picks this provider for the process (the
 * {@code slf4j.provider} property) before the first logger is made; it is not registered as a service, so
 * tests and embedded uses keep slf4j-simple.
 */
package org.fdnet.logging;

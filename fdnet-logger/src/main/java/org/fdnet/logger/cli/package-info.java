/**
 * The logger's commands: {@code fdnet logger} (headless status line or {@code --gui}) and
 * {@code fdnet bench logger} (producer process → logger → PostgreSQL, beside raw COPY in the same run).
 *
 * <pre>
 *   fdnet logger ─▶ LoggerCommand ─▶ LoggerConfigFile + options ─▶ NetworkStateLogger | LoggerFrame
 *   fdnet bench logger ─▶ BenchLoggerCommand ─spawn─▶ BenchProducer (LoggerClient) ─TCP─▶ logger ─COPY─▶ DB
 * </pre>
 */
package org.fdnet.logger.cli;

/**
 * The logger's command: {@code fdnet logger} (headless status line or {@code --gui}), registered by
 * {@link org.fdnet.logger.cli.LoggerCommands}.
 *
 * <pre>
 *   fdnet logger ─▶ LoggerCommand ─▶ LoggerConfigFile + options ─▶ NetworkStateLogger | LoggerFrame
 * </pre>
 *
 * <p>The same package in fdnet-logger/bench holds {@code fdnet bench logger}, registered there by
 * {@code LoggerBenchmarks} with {@code fdnet soak} ({@code org.fdnet.logger.soak}); the logger's jar carries neither:
 * <pre>
 *   fdnet bench logger ─▶ BenchLoggerCommand ─spawn─▶ ProducerProcess/BenchProducer (LoggerClient) ─TCP─▶ logger ─COPY─▶ DB
 *                           │ (sustained, latency at a fixed rate, burst)      BatchObserver: batch sizes, commit latency
 *                           ├─▶ RawCopyBaseline (same rows, the writer's batch sizes; 100,000-row keyed limit)
 *                           └─▶ TargetReport (each figure beside its target: met / NOT MET; summary)
 * </pre>
 */
package org.fdnet.logger.cli;

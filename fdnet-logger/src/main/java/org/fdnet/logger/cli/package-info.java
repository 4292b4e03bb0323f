/**
 * The logger's commands: {@code fdnet logger} (headless status line or {@code --gui}) and
 * {@code fdnet bench logger} (producer process → logger → PostgreSQL, beside raw COPY in the same run).
 *
 * <pre>
 *   fdnet logger ─▶ LoggerCommand ─▶ LoggerConfigFile + options ─▶ NetworkStateLogger | LoggerFrame
 *   fdnet bench logger ─▶ BenchLoggerCommand ─spawn─▶ ProducerProcess/BenchProducer (LoggerClient) ─TCP─▶ logger ─COPY─▶ DB
 *                           │ (sustained, latency at a fixed rate, burst)      BatchObserver: batch sizes, commit latency
 *                           ├─▶ RawCopyBaseline (same rows, the writer's batch sizes; 100,000-row keyed limit)
 *                           └─▶ TargetReport (each figure beside its target: met / NOT MET; summary)
 * </pre>
 */
package org.fdnet.logger.cli;

/**
 * The logger's benchmarks behind {@code fdnet bench logger}: producer processes, the raw COPY baseline, the batch-
 * size sweep and the report against targets; and {@code fdnet bench export}: a recorded run of a million events
 * exported to MCAP and CSV, against the same rows copied bare out of PostgreSQL in the same run.
 *
 * <pre>
 *   ExportBenchRun.fill ─COPY─▶ throwaway PostgreSQL ─┬─ COPY (SELECT …) TO STDOUT ─▶ /dev/null      (the baseline)
 *                                                     └─ RunExport ─▶ McapRunSink / LongCsvSink ─▶ file (the export)
 * </pre>
 */
package org.fdnet.logger.bench;

/**
 * A recorded run as a file other tools open: MCAP (Foxglove, PlotJuggler, Python's and TypeScript's readers) or CSV
 * (long and wide tables). {@link org.fdnet.logger.export.StoredRuns} finds a run as the viewer names it,
 * {@link org.fdnet.logger.export.StoredRows} streams its rows in time order on the run's common clock,
 * a {@link org.fdnet.logger.export.RunSink} writes them; {@link org.fdnet.logger.export.McapWriter} is the MCAP
 * format itself (records, zstd chunks, indexes, summary, CRCs). Parts that know a kind of run add 3D topics through
 * {@link org.fdnet.logger.export.SceneSource} (roq-sim draws RoQ) without the logger depending on them.
 *
 * <pre>
 *   PostgreSQL ─COPY (SELECT … ORDER BY common time) TO STDOUT─▶ StoredRows ─ExportRow (reused)─▶ RunSink
 *        McapRunSink: ValueJson + MessageSchemas ─▶ McapWriter ─▶ .mcap      ◀── RunScene topics (ServiceLoader)
 *        LongCsvSink / WideCsvSink ─▶ .csv
 *   viewer's Export…: LoggerConnection.history ─▶ ExportRow ─▶ the same sinks
 * </pre>
 */
package org.fdnet.logger.export;

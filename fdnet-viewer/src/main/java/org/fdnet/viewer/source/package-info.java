/**
 * Where the viewer's values come from: the logger's sender server. {@link
 * org.fdnet.viewer.source.LoggerConnection} lists nodes and runs, monitors nodes live and loads history
 * (cache + database, merged by the logger); {@link org.fdnet.viewer.source.Replay} plays a past run's
 * history back at a chosen speed.
 *
 * <pre>
 *   core ─LoggerClient─▶ logger ─MONITOR_EVENTS─▶ LoggerConnection ─▶ PlotData (live)
 *                               ─HISTORY──────────▶ LoggerConnection ─▶ PlotData (a time range)
 *                               ─HISTORY (past run)─▶ Replay (1×, 2×, 10×, pause) ─▶ PlotData
 * </pre>
 *
 * No protocol change was needed: NODE_LIST names each node's run, so the runs are the distinct run ids of
 * the node list, and a past run's values are the HISTORY of its nodes' source ids.
 */
package org.fdnet.viewer.source;

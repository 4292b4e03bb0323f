/**
 * The viewer's screen: {@link org.fdnet.viewer.ui.ViewerWindow} (node picker, tool bar, replay bar) around
 * {@link org.fdnet.viewer.ui.PlotPanel} (one canvas, one lane per unit, min/max per pixel column, 30
 * frames/s), and {@link org.fdnet.viewer.ui.CsvExport}.
 *
 * <pre>
 *   LoggerConnection ─▶ PlotData (live) ─▶ PlotPanel ◀─ wheel zoom, drag pan, space pause, cursor read-out
 *   history button ─HistoryLoader (own thread)─▶ PlotData (range) ─event thread─▶ PlotPanel (paused on the range)
 *   replay bar ─ReplayLoader─▶ Replay ─▶ PlotData (replayed) ─▶ PlotPanel
 *   visible window of the shown PlotPanel ─▶ CsvExport ─▶ file.csv
 * </pre>
 *
 * The editor (or any program) opens a plot for chosen nodes with
 * {@code ViewerWindow.open("127.0.0.1:5556", List.of("Balance/keep a balance", "Pose/pitch[rad]"))}.
 */
package org.fdnet.viewer.ui;

/**
 * The viewer's screen: {@link org.fdnet.viewer.ui.ViewerWindow} — the logger's runs and the chosen run's Datas
 * as a tree ({@link org.fdnet.viewer.ui.NodeTree}) on the left, the plots ({@link org.fdnet.viewer.ui.PlotGrid} of
 * {@link org.fdnet.viewer.ui.PlotView}s, each a {@link org.fdnet.viewer.ui.PlotPanel}: min/max per pixel column,
 * 30 frames/s) on one shared {@link org.fdnet.viewer.ui.TimeAxis}, the tool bar
 * ({@link org.fdnet.viewer.ui.ViewerActions}, where every action is registered) and the replay bar.
 *
 * <pre>
 *   NodeTree ─drag (SeriesTransfer) / Add to plot─▶ PlotGrid.addSeries ─unit fits?─▶ PlotView (refused: status bar)
 *   LoggerConnection ─▶ PlotData (live) ─┐
 *   History ─HistoryLoader─▶ PlotData ───┼─ PlotGrid.show ─▶ every PlotPanel draws its series from it
 *   replay bar ─ReplayLoader─▶ Replay ───┘        ▲ wheel zoom, drag pan, space pause, cursor: TimeAxis (shared)
 *   series of every plot, visible window ─▶ CsvExport ─▶ file.csv;  PlotGrid ⇄ ViewerLayout (layout package)
 * </pre>
 *
 * The editor (or any program) opens a plot for chosen nodes with
 * {@code ViewerWindow.open("127.0.0.1:5556", List.of("Balance/keep a balance", "Pose/pitch[rad]"))}.
 */
package org.fdnet.viewer.ui;

/**
 * The Network State Viewer: live and historical plots of node values, a client of the logger's sender
 * server (thesis Chapter 4, the viewer service; Chapter 5 §VIII–IX).
 *
 * <pre>
 *   network ─LoggerClient─▶ logger (cache + PostgreSQL) ─sender server─▶ source.LoggerConnection / Replay
 *        ─▶ data.PlotData (Series per number) ─▶ ui.PlotGrid (plots on one time axis) in ui.ViewerWindow
 *   layout.ViewerLayout (file, or RoQ's ready one) ⇄ ui.PlotGrid
 * </pre>
 *
 * Packages: {@code data} (series, units), {@code source} (logger connection, replay), {@code ui} (window, plots,
 * node tree, CSV export), {@code layout} (layout files and the shipped layouts), {@code cli} ({@code fdnet viewer}; {@code fdnet bench viewer} is fdnet-viewer/bench's). Public API for the editor:
 * {@link org.fdnet.viewer.ui.ViewerWindow#open(String, java.util.List)}.
 */
package org.fdnet.viewer;

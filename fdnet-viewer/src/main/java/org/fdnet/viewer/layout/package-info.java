/**
 * What a viewer window shows apart from the data: its plots and their series with units, the time window and the
 * legend ({@link org.fdnet.viewer.layout.ViewerLayout}), kept in a small text file
 * ({@link org.fdnet.viewer.layout.LayoutFile}, {@code fdnet viewer --layout FILE}) and shipped ready for known
 * networks ({@link org.fdnet.viewer.layout.ReadyLayouts}: RoQ's).
 *
 * <pre>
 *   --layout FILE ─LayoutFile.read─┐
 *   run's node names ─ReadyLayouts─┼─▶ ViewerLayout ─▶ PlotGrid.apply (plots, units into the UnitBook)
 *   Save layout… ◀─LayoutFile.write─┘◀── PlotGrid.currentLayout()
 * </pre>
 */
package org.fdnet.viewer.layout;

/**
 * What the viewer plots: {@link org.fdnet.viewer.data.Series} (time/value samples of one line, with its
 * unit) and {@link org.fdnet.viewer.data.PlotData} (all series of one viewer, keyed by the logger's source
 * id). Sources (live monitor, history, replay) write in; the plot panel and the CSV export read out.
 *
 * <pre>
 *   DataValueEvent ──▶ PlotData.accept ──SampleDecoder──▶ Series (one per number) ──▶ PlotPanel / CsvExport
 * </pre>
 */
package org.fdnet.viewer.data;

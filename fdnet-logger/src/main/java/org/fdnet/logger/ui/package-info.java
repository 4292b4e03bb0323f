/**
 * The logger's configuration panel (thesis, chapter 4 VIII), Swing with FlatLaf.
 *
 * <pre>
 *   LoggerFrame ─▶ LoggerPanel ─┬─ SettingsTab × 5 (database, writer, receiver, sender, memory &amp; priority):
 *                               │    a SettingField per setting (label, field, unit, help; checked as typed;
 *                               │    live ones ─applyLive─▶ NetworkStateLogger while it runs)
 *                               ├─ Load… / Save… ⇄ LoggerConfigFile
 *                               ├─ ClientTableModel × 2 (address, port, name, state, frames, end reason)
 *                               ├─ CacheBrowser: pick a Data ─cache().entriesOf(id)─▶ CacheEntryTableModel
 *                               └─ Start/Stop/Retry database ─SwingWorker─▶ NetworkStateLogger;
 *                                  Timer(500 ms) ─status()─▶ labels
 * </pre>
 *
 * Component names tests use: {@code start}, {@code stop}, {@code retry}, {@code load}, {@code save}, {@code status},
 * {@code message}, each setting's help line {@code KEY.help},
 * {@code cache}, {@code rates}, {@code database}, {@code tabs}, {@code cores}, {@code viewers}, {@code cacheNode},
 * {@code cacheRefresh}, {@code cacheEvents}, {@code cacheSummary}, and each field by its setting's key.
 */
package org.fdnet.logger.ui;

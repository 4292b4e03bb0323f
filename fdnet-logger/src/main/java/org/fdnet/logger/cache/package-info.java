/**
 * The logger's indexed event cache (thesis, chapter 4 IV): two event containers indexed by node id, then
 * time — network state (with monitoring: a duplicated index for events still owed to monitors) and network
 * commands — and the queue of events not yet written.
 *
 * <pre>
 *   receiver ─▶ EventCache.add ─┬─▶ MonitoredEventContainer (states)  ─offer─▶ MonitorSubscriber (viewers)
 *                               ├─▶ EventContainer (commands)
 *                               └─▶ unwritten queue ─takeBatch─▶ BatchWriter ─commit─▶ committed()
 *   an event leaves memory only when committed AND no monitor still waits for it
 *   usedBytes ≥ critical → pressured (receivers wait, writer full rate) … ≤ normal → released
 * </pre>
 */
package org.fdnet.logger.cache;

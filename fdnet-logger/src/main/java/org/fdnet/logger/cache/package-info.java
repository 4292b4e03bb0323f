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
 *   viewer ─▶ EventCache.history ─▶ the node's NodeTimeline, under its own lock (not the cache's)
 * </pre>
 *
 * <p>Locks: the cache's lock guards accounting, the queue, monitors and every change; each NodeTimeline's
 * own lock is taken inside it by changes and alone by queries — never the other way round.
 */
package org.fdnet.logger.cache;

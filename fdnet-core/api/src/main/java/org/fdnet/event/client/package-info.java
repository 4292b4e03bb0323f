/**
 * The clients of the logger: the core's event cache and sender ({@link org.fdnet.event.client.LoggerClient},
 * an {@link org.fdnet.event.EventSink}) and the viewers' client ({@link org.fdnet.event.client.ViewerClient}).
 *
 * <pre>
 *   runtime ─accept()─▶ LoggerClient: memory ─(full)─▶ SpillJournal (disk, bounded; beyond: counted loss)
 *                            │ EVENTS(seq…)                 ▲ ACK(seq committed) frees memory/journal
 *                            ▼                              │
 *                         logger receiver ─▶ cache ─▶ writer ─COPY─▶ PostgreSQL
 *   viewer ─ViewerClient─▶ logger sender: LIST_NODES, HISTORY, MONITOR/UNMONITOR
 *   logger sender ─frames─▶ ViewerClient's reader ─LoggerAnswers─▶ open requests' answers, monitor listener
 * </pre>
 * The threads a waiting viewer depends on (the logger's sender thread, the viewer's reader) make themselves
 * real-time where permitted ({@link org.fdnet.event.client.ResponsiveThreads}).
 */
package org.fdnet.event.client;

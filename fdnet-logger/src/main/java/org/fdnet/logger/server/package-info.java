/**
 * The logger's two TCP servers, each built as the thesis's three layers: {@link org.fdnet.logger.server.TcpServer}
 * (accepts) → {@link org.fdnet.logger.server.ConnectionFactory} (limits, creates, tracks states) →
 * {@link org.fdnet.logger.server.Connection} (one thread per client; handshake and protocol errors shared).
 *
 * <pre>
 *   core   ─TCP 5555─▶ TcpServer ─▶ ConnectionFactory ─▶ ReceiverConnection ─EVENTS─▶ EventCache
 *                                                           ◀─ACK(seq)── writer commits (RunProgress)
 *   viewer ─TCP 5556─▶ TcpServer ─▶ ConnectionFactory ─▶ SenderConnection ─HISTORY─▶ ViewerService (cache + DB)
 *                                                           │     values in binary (a number: 22 bytes, no text)
 *                                                           └─MONITOR─▶ MonitorStream ◀─offer── EventCache
 *   bad frame → ERROR + close that connection only (logged); states: waiting → activated → stopped
 * </pre>
 */
package org.fdnet.logger.server;

/**
 * The network state logger (thesis, chapter 4): {@link org.fdnet.logger.NetworkStateLogger} assembles the
 * receiver server, the indexed event cache, the batch writer to PostgreSQL and the sender server for
 * viewers from one sealed configuration. Its promise: no event lost, none stored twice.
 *
 * <pre>
 *   core (LoggerClient) ─EVENTS─▶ server.ReceiverConnection ─▶ cache.EventCache ─▶ writer.BatchWriter
 *        ▲                                 (pressured: stop reading)      │ COPY, one transaction per batch
 *        └────────────── ACK(seq) ◀── cache.RunProgress ◀── commit ◀──────┴──▶ store.EventStore ─▶ PostgreSQL
 *   viewer (ViewerClient) ─▶ server.SenderConnection ─▶ server.ViewerService (cache, else flush + cache + DB)
 *   config.LoggerConfig ─▶ cli.LoggerCommand (headless status line) | ui.LoggerPanel (tabs, Start/Stop, status)
 * </pre>
 */
package org.fdnet.logger;

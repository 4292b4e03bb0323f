/**
 * The logger's PostgreSQL side: the schema (the thesis's three tables plus runs and node names), the
 * embedded server, the batch path (COPY, one transaction per batch) and the queries viewers need.
 *
 * <pre>
 *   BatchWriter ─writeBatch(batch, new mappings)─▶ EventStore ─BEGIN; INSERT fdnet_node; COPY datavalue_log,
 *                                                   procvalue_log, netcommand_log (sorted); UPDATE fdnet_run; COMMIT
 *   receiver HELLO ─▶ SourceDirectory.openRun ─▶ fdnet_run        viewer ─▶ EventStore.history ─▶ 3 tables
 *   EmbeddedDatabase (default) or DatabaseTarget(--db URL)
 *   openWriterConnection ─pg_backend_pid()─▶ BackendNiceness ─renice─▶ the writer's backends at writer.backendNiceness
 *   sender answering from the cache ─begin/end─▶ QueryPriority ◀─yieldToQueries─ writer lanes, receivers (if paused)
 * </pre>
 */
package org.fdnet.logger.store;

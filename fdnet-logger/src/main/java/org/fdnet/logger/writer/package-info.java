/**
 * The batch writer: the cache's only way out to PostgreSQL.
 *
 * <pre>
 *   EventCache.awaitUnwritten(batchSize | timer) ─takeBatch─▶ BatchWriter ─EventStore.writeBatch (COPY, commit)─▶ DB
 *        ▲                                                        │ on success: cache.committed(batch) → evict, ACK cores
 *        └── pressured / flush(): no timer, back to back ◀────────┘ on failure: same batch again after a delay, forever
 * </pre>
 */
package org.fdnet.logger.writer;

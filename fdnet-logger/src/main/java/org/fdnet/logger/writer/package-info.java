/**
 * The batch writer: the cache's only way out to PostgreSQL.
 *
 * <pre>
 *   EventCache.awaitUnwritten(batchSize | timer) ─takeBatch(BatchSizer: grows with the backlog, ≤ max rows/bytes)
 *        │                                                  ─▶ BatchWriter ─EventStore.writeBatch (COPY, commit)─▶ DB
 *        │                                                        │ then BatchObserver (benchmarks)
 *        ▲                                                        │ on success: cache.committed(batch) → evict, ACK cores
 *        └── pressured / flush(): no timer, back to back ◀────────┘ on failure: same batch again after a delay, forever
 * </pre>
 */
package org.fdnet.logger.writer;

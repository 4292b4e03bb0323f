/**
 * The batch writer: the cache's only way out to PostgreSQL.
 *
 * <pre>
 *   EventCache.awaitUnwritten(batchSize | timer) ─takeBatch(BatchSizer: grows with the backlog, ≤ max rows/bytes)
 *        │                                                  ─▶ BatchWriter ─▶ WriterLane 1..writer.connections
 *        │                                                        │            (EventStore.copyBatch, then
 *        │                                                        │             commitBatch once the batch
 *        │                                                        │             before committed) ─▶ DB
 *        ▲                                                        │ oldest first: BatchObserver (benchmarks),
 *        │                                                        │ cache.committed(batch) → evict, ACK cores
 *        └── pressured / flush(): no timer, back to back ◀────────┘ on failure: it and the batches behind it
 *                                                                   (rolled back) again, in order, one at a time
 * </pre>
 * With several connections a free lane gets the next batch (what is ready, at least the pipeline floor of
 * 10,000 events) while the others write, so no lane waits for the clients' ACK cycle while enough is ready.
 */
package org.fdnet.logger.writer;

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
 * With several connections a batch takes a share of what the writer holds (waiting + in flight, over
 * connections + 1), so a batch is ready when a lane frees even when the clients' windows bound the backlog.
 */
package org.fdnet.logger.writer;

/**
 * The events of a running network and where they go.
 *
 * <pre>
 *   runtime (Data write, Relation status, structural command)
 *        │  stamps time with EventClock (unique, strictly increasing); a Data's event carries the value's
 *        │  own TypedValue (shared, immutable: nothing is formatted inside the commit lock)
 *        ▼
 *   NetworkEvent ──▶ EventSink.accept()  (never blocks a Relation)
 *                       ├── MemoryEventSink   (tests, run summaries)
 *                       └── logger client     (Part 4: cache → journal → TCP → logger)
 * </pre>
 *
 * The four event kinds map onto the logger's tables: {@link org.fdnet.event.DataValueEvent} →
 * {@code datavalue_log}, {@link org.fdnet.event.RelationValueEvent} → {@code procvalue_log},
 * {@link org.fdnet.event.NetworkCommandEvent} → {@code netcommand_log}, and
 * {@link org.fdnet.event.NodeNamedEvent} → the table that names nodes. This package depends on {@code netinfo}
 * only, never on the runtime: it is the API that the logger and the viewers share with the cores.
 */
package org.fdnet.event;

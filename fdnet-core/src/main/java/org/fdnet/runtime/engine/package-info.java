/**
 * The engine that runs a {@link org.fdnet.netinfo.NetworkInfo} on one host:
 * {@link org.fdnet.runtime.engine.RuntimeNetwork} (started with {@link org.fdnet.runtime.engine.RuntimeOptions}, on
 * real time or a {@link org.fdnet.runtime.engine.DrivenClock}), the dataflow of values (Dataflow, Scheduler, DataNode,
 * RelationNode, FiringContext, EventPublisher), the structure (NodeFactory, StructurePlan, Wiring, Rewiring) and the
 * implementation of the {@link org.fdnet.runtime.Controller} and of the Servants' scopes (EngineScope on this engine,
 * WholeNetworkScope over every host).
 *
 * <p>It is built on the runtime's public API ({@code org.fdnet.runtime}), which never imports it: the engine
 * implements the API's {@link org.fdnet.runtime.Data.DataPort} (DataNode) and {@link org.fdnet.runtime.ServantScope},
 * calls the authors' protected life-cycle methods through {@link org.fdnet.runtime.NodeLifecycle}, and builds each
 * Relation's {@link org.fdnet.runtime.Servants} (EngineServants). Node authors never import this package; tools
 * (cli, run, corba, hi, roq-sim, benchmarks) do, to start a network. docs/explanation/runtime.md describes the semantics.
 *
 * <h2>Flow of one value</h2>
 * <pre>
 *   setValue / SensorData.push / a Relation's firing
 *        │  DataNode.prepare: convert to the Data's type, Data.accept (outside any lock)
 *        ▼
 *   Dataflow.commit: commit lock ─ stamp (EventClock) ─ store ─ DataValueObservers
 *        │  EventPublisher: DataValueEvent ─▶ EventSinks
 *        │  (all outputs of one firing under one lock: readers never see half of it)
 *        ▼
 *   each Relation it triggers (not the writer itself) ── IDLE→QUEUED ──▶ Scheduler
 *        ├─ on this thread, after the current firing (run-to-completion, ~0.2 µs a hop)
 *        └─ on the bounded worker pool (timer, budget spent, idle worker for parallel work)
 *   RelationNode fires: FiringContext snapshots its inputs (optimistic read of the commit lock)
 *        → Relation.compute → Dataflow.commit of its outputs
 * </pre>
 * Each value carries a source tick ({@link org.fdnet.runtime.Value#tick()}): the sensor snapshot it came from,
 * set by the pusher; a firing's outputs get the newest tick of the inputs it read (one long per value, no
 * allocation unless it changes). {@link org.fdnet.runtime.SensorData#pushTogether} commits several sensors'
 * values under one lock, so no Relation sees half of one snapshot.
 *
 * <h2>Structure</h2>
 * <pre>
 *   Controller request (edit, parameter, load/unload/hold/resume, restart) — also from Servants
 *        │  structure lock; edit a COPY of the definition (refused → nothing changed)
 *        ▼
 *   StructurePlan (loaded modules × Placement) → construct new nodes (failure → refused)
 *        ▼
 *   commit: DISCONNECT, DESTROY, CREATE, CONNECT events; Rewiring; statuses
 *        ▼  after the lock
 *   new and rewired Relations fire once
 * </pre>
 *
 */
package org.fdnet.runtime.engine;

/**
 * The FDNet runtime on one host: the programming model for node authors ({@link org.fdnet.runtime.Data},
 * {@link org.fdnet.runtime.SensorData}, {@link org.fdnet.runtime.Relation},
 * {@link org.fdnet.runtime.RelationContext}, {@link org.fdnet.runtime.Value}), the Servants a Relation reshapes
 * the network with ({@link org.fdnet.runtime.Servants}), the engine that runs a
 * {@link org.fdnet.netinfo.NetworkInfo} ({@link org.fdnet.runtime.engine.RuntimeNetwork}), and the one surface
 * everybody else acts through ({@link org.fdnet.runtime.Controller}).
 *
 * <p>The Servants live in this package, not a sub-package: a Relation's context hands them out
 * ({@code RelationContext.servants()}) and they speak Values, ChangeOutcomes and NetworkEdits, so the two are one
 * API; as two packages they were an import cycle. Everything above this package (library, loading, control,
 * corba, run, the tools) imports it; it imports only {@code netinfo} and {@code event} (fdnet-api).
 *
 * <h2>Flow of one value</h2>
 * <pre>
 *   setValue / SensorData.push / a Relation's firing
 *        │  convert to the Data's type, Data.accept (outside any lock)
 *        ▼
 *   commit lock ─ stamp (EventClock) ─ store ─ DataValueObservers ─ DataValueEvent ─▶ EventSinks
 *        │  (all outputs of one firing under one lock: readers never see half of it)
 *        ▼
 *   each Relation it triggers (not the writer itself) ── IDLE→QUEUED ──▶ Scheduler
 *        ├─ on this thread, after the current firing (run-to-completion, ~0.2 µs a hop)
 *        └─ on the bounded worker pool (timer, budget spent, idle worker for parallel work)
 *   Relation fires: snapshot of its inputs (optimistic read of the commit lock) → compute → commit
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
 * <h2>Seams for distribution (Part 3)</h2>
 * <ol>
 * <li><b>Placement</b> — {@link org.fdnet.runtime.engine.RuntimeOptions#placement(Placement)} with a
 *     {@link org.fdnet.runtime.Placement} decides which nodes this process instantiates. Default
 *     {@link org.fdnet.runtime.Placement#all()}; {@link org.fdnet.runtime.Placement#thisHost()} keeps nodes whose
 *     {@code host} is localhost, 127.0.0.1, ::1, empty or this machine's name;
 *     {@link org.fdnet.runtime.Placement#forHostNames(java.util.Set)} for a named host.</li>
 * <li><b>Value observers</b> — {@link org.fdnet.runtime.Controller#observe} registers a
 *     {@link org.fdnet.runtime.DataValueObserver} that sees every value of a Data in the Data's own order
 *     (called under the commit lock: enqueue and return). It follows the Data through unload, reload and
 *     parameter changes.</li>
 * <li><b>Injection</b> — {@link org.fdnet.runtime.Controller#setValue} writes a value into a local Data (or a
 *     stand-in) from outside, exactly as a Relation would; a {@link org.fdnet.runtime.SensorData} can push too.</li>
 * <li><b>Remote stand-ins</b> — a connection whose other end is not local never crashes the engine: a local
 *     Relation that reads or writes a remote Data gets a local stand-in of it (no events of its own; feed it with
 *     setValue, forward its values with observe); a remote Relation on a local Data is simply recorded.
 *     {@link org.fdnet.runtime.Controller#remoteLinks()} lists them, broken ones with the reason.</li>
 * </ol>
 *
 * <h2>Servants (thesis Appendix 2)</h2>
 * The network-wide API a Relation uses to see and reshape the whole network. Not CORBA servants (those are the
 * {@code …Impl} classes of the distribution layer).
 * <pre>
 *   Relation.compute(ctx) ──▶ ctx.servants()
 *        ├── Visitor          find running nodes (by class, by name, by predicate)
 *        ├── Reflect          describe one node: definition, value/state, connections
 *        ├── Paste            create/destroy nodes, connect/disconnect/activate ──┐
 *        ├── NetworkIterator  follow the flow of values (the thesis's Iterator)     │ change requests of the
 *        ├── LinkageIterator  the connections crossed, live or dormant             │ network's Controller,
 *        └── load/unload/hold/resume modules ───────────────────────────────────────┘ logged with the Relation
 *                                                                                     as source ("proc")
 * </pre>
 *
 * <p>Where they look: {@link org.fdnet.runtime.ServantScope}. On one host, the engine itself
 * ({@code EngineScope}). On a host of a distributed network, the {@link org.fdnet.runtime.WholeNetwork}
 * the distribution layer installed ({@code WholeNetworkScope}): the whole definition and where each node runs come
 * from the network's coordinator, this host's own nodes are read from its engine, others' values from their host,
 * and every change is prepared and committed on every host it touches.
 * <pre>
 *   Visitor / Reflect / Iterators ─▶ snapshot (definition + loaded modules + node → host) ─▶ descriptions
 *   Paste / load / unload / hold / resume ─▶ WholeNetwork ─▶ coordinator ─▶ every host it touches (or refused)
 * </pre>
 *
 * <p>The servant system proper ({@link org.fdnet.runtime.ServantRegistry}, one per engine): servant classes
 * and their {@code name:N} instances, the tree of {@link org.fdnet.runtime.ServantNode}s from the root, and
 * typed messages between Relations answered through a {@link org.fdnet.runtime.ReturnListener}:
 * <pre>
 *   Relation A ─sendMessage(path, message, Value)─▶ messaging thread ─▶ tree here: MessageServant.answer
 *                                                                   └▶ else WholeNetwork.message ─▶ other hosts
 *   ReturnListener.returned(reply) / refused(reason) ◀───────────────────────────────────────────────┘
 * </pre>
 */
package org.fdnet.runtime;

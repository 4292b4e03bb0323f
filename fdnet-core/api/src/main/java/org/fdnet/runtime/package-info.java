/**
 * The FDNet runtime's public API: the programming model for node authors ({@link org.fdnet.runtime.Data},
 * {@link org.fdnet.runtime.SensorData}, {@link org.fdnet.runtime.Relation},
 * {@link org.fdnet.runtime.RelationContext}, {@link org.fdnet.runtime.Value},
 * {@link org.fdnet.runtime.NodeParameters}), the Servants a Relation reshapes the network with
 * ({@link org.fdnet.runtime.Servants}), and the one surface everybody else acts through
 * ({@link org.fdnet.runtime.Controller}). The engine that runs a {@link org.fdnet.netinfo.NetworkInfo}
 * ({@code RuntimeNetwork}) is {@code org.fdnet.runtime.engine}, one layer up.
 *
 * <p>A node's parameters are declared once, in its class:
 * <pre>
 *   static final ParameterSpec fields ──▶ DeclaredParameters (the class's own, then Relation's/Data's: period, ...)
 *        │                                  ├──▶ engine: checked before init (ParameterException: module, node,
 *        │                                  │    parameter, range); a live change of one not declared live refused
 *        │                                  └──▶ fdnet info --params, the editor's node form (descriptions)
 *        └──▶ init: SPEC.read(parameters) ──▶ the value, default applied
 * </pre>
 * {@link org.fdnet.netinfo.ValueRange} words every range, here and in the logger's settings.
 *
 * <p>This package imports nothing of the engine (ArchitectureTest fails the build otherwise); it imports only
 * {@code netinfo} and {@code event} (fdnet-api). Where the API must reach the engine, the engine implements an
 * interface of this package: {@link org.fdnet.runtime.Data.DataPort} (a Data's current value, its pushes,
 * {@link org.fdnet.runtime.SensorData#pushTogether}), {@link org.fdnet.runtime.ServantScope} (what the Servants
 * read and change). The engine calls the authors' protected life-cycle methods through
 * {@link org.fdnet.runtime.NodeLifecycle} and builds each Relation's Servants from their parts.
 *
 * <p>The Servants live in this package, not a sub-package: a Relation's context hands them out
 * ({@code RelationContext.servants()}) and they speak Values, ChangeOutcomes and NetworkEdits, so the two are one
 * API; as two packages they were an import cycle. Everything above this package (library, engine, loading, control,
 * corba, run, the tools) imports it.
 *
 * <h2>Seams for distribution (Part 3)</h2>
 * <ol>
 * <li><b>Placement</b> — {@code engine.RuntimeOptions#placement(Placement)} with a
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

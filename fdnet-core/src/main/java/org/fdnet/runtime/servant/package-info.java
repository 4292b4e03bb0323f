/**
 * FDNet's Servants (thesis Appendix 2): the network-wide API a Relation uses to see and reshape the whole
 * network. Not CORBA servants (those are the {@code …Impl} classes of the distribution layer).
 *
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
 * <p>Where they look: {@link org.fdnet.runtime.servant.ServantScope}. On one host, the engine itself
 * ({@code EngineScope}). On a host of a distributed network, the {@link org.fdnet.runtime.servant.WholeNetwork}
 * the distribution layer installed ({@code WholeNetworkScope}): the whole definition and where each node runs come
 * from the network's coordinator, this host's own nodes are read from its engine, others' values from their host,
 * and every change is prepared and committed on every host it touches.
 * <pre>
 *   Visitor / Reflect / Iterators ─▶ snapshot (definition + loaded modules + node → host) ─▶ descriptions
 *   Paste / load / unload / hold / resume ─▶ WholeNetwork ─▶ coordinator ─▶ every host it touches (or refused)
 * </pre>
 *
 * <p>The servant system proper ({@link org.fdnet.runtime.servant.ServantRegistry}, one per engine): servant classes
 * and their {@code name:N} instances, the tree of {@link org.fdnet.runtime.servant.ServantNode}s from the root, and
 * typed messages between Relations answered through a {@link org.fdnet.runtime.servant.ReturnListener}:
 * <pre>
 *   Relation A ─sendMessage(path, message, Value)─▶ messaging thread ─▶ tree here: MessageServant.answer
 *                                                                   └▶ else WholeNetwork.message ─▶ other hosts
 *   ReturnListener.returned(reply) / refused(reason) ◀───────────────────────────────────────────────┘
 * </pre>
 */
package org.fdnet.runtime.servant;

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
 */
package org.fdnet.runtime.servant;

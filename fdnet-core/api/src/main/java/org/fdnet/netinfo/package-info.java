/**
 * NetworkInfo: the logical layer of a network definition, with no I/O.
 *
 * <pre>
 *   NetworkInfo ── modules (ordered) ──▶ ModuleInfo ── nodes (ordered) ──▶ NodeInfo (Data | Relation)
 *        │                                   └──── connections ─────────▶ ConnectionInfo (Reader | Writer)
 *        ├── edits: add/delete/rename module, add/update/delete/rename/replace/merge node, add/delete connection
 *        ├── queries: resolve name, connectionsOf, ancestors, descendants, counts  (via ConnectionIndex)
 *        └── NetworkChangeListener ◀── one NetworkChange per completed edit
 * </pre>
 *
 * Nodes and connections are immutable values; every edit goes through {@link org.fdnet.netinfo.NetworkInfo},
 * checks first and changes after, so a refused edit ({@link org.fdnet.netinfo.EditRefusedException}) leaves
 * the model untouched. The rules shared with the file loader live in {@link org.fdnet.netinfo.ModelRules}.
 * View state (positions, colours, visibility) never enters this package: see {@code org.fdnet.layout}.
 */
package org.fdnet.netinfo;

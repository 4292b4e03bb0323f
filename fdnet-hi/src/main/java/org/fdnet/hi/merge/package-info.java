/**
 * The Merge/Replace dialog (thesis Chapter 5 §VII, Figures 28–29): shown when a new or renamed node is to take
 * a name that another node of its module already has. The user chooses Replace, or Merge with a parameter
 * policy ({@link org.fdnet.netinfo.MergePolicy}: the existing node's, the incoming node's, or both); the choice
 * is applied as one edit through {@link org.fdnet.hi.edit.NetworkEditor}.
 *
 * <pre>
 *   rename / add with a used name ─▶ MergeReplaceDialog (view) ─▶ MergeReplaceChoice (logic)
 *                                                                  ─▶ NetworkEditor.replaceNode / mergeNodes
 *                                                                  ─▶ NetworkInfo ─▶ change listeners (all views)
 * </pre>
 *
 * Entry points for the application: {@code MergeReplaceDialog.renameOrAsk(owner, editor, ref, newName)} renames
 * a node or asks; {@code new MergeReplaceDialog(owner, editor, incoming, takenName)} then {@code setVisible(true)}
 * and {@code result()} (null when cancelled) when the incoming node is already in the network.
 */
package org.fdnet.hi.merge;

/**
 * Editing a network in the Human Interface: {@link org.fdnet.hi.edit.NetworkEditor} is the single door every
 * view edits through (one undoable step per call, refusals change nothing).
 *
 * <pre>
 *  graphic panel ─┐
 *  text frames ───┼─▶ NetworkEditor ─▶ NetworkInfo edit ─▶ change listeners ─▶ every view repaints
 *  dialogs ───────┘        └─▶ undo/redo history, dirty marker (live mode: the running network first)
 * </pre>
 *
 * <p>{@link org.fdnet.hi.edit.UndoableNetworkEditor} implements the door. Each call builds a
 * {@link org.fdnet.hi.edit.ReversibleEdit}; applying it to the network returns its inverse (deleteNode's
 * inverse re-adds the node and each of its connections at their places), which goes on the undo stack of
 * {@link org.fdnet.hi.edit.EditHistory}; applying an inverse returns the redo. No step copies the model —
 * except in live mode, where an {@link org.fdnet.hi.edit.EditGate} is set: each edit, undo and redo is first tried
 * on a copy, the gate sends the result to the running network, and only an executed change is applied here.
 * Changes the running network made by itself come in through {@code adopt}, outside the history.
 *
 * <pre>
 *  editor.deleteNode(r) ─▶ NodeEdits.delete(r).applyTo(target) ─▶ NetworkInfo.deleteNode(r)
 *                                   └─ returns [addNode(r, at i), addConnection(c, at j)…] ─▶ undo stack
 *  editor.undo() ─▶ inverse.applyTo(target) ─▶ returns the redo edit ─▶ redo stack
 * </pre>
 */
package org.fdnet.hi.edit;

/**
 * Editing a network in the Human Interface: {@link org.fdnet.hi.edit.NetworkEditor} is the single door every
 * view edits through (one undoable step per call, refusals change nothing).
 *
 * <pre>
 *  graphic panel ─┐
 *  text frames ───┼─▶ NetworkEditor ─▶ NetworkInfo edit ─▶ change listeners ─▶ every view repaints
 *  dialogs ───────┘        └─▶ undo/redo history, dirty marker (live mode: the running network first)
 * </pre>
 */
package org.fdnet.hi.edit;

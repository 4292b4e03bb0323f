/**
 * Live mode: the editor attached to a running network ({@link org.fdnet.control.LiveNetwork}, in this process or
 * reached through its control object). A {@link org.fdnet.hi.live.LiveSession} is one attachment.
 *
 * <pre>
 *  user edit ─▶ UndoableNetworkEditor ─try on a copy─▶ EditGate = LiveSession.sendEdit
 *                      ▲                     ─NetworkCallThread (Swing keeps dispatching: "Sending …")─▶ apply(base, edited) ─▶ network
 *                      │  executed: apply here, undo step               refused: nothing here, status bar says why
 *  module list, "send a value", deploy ─▶ the same NetworkCallThread, one change at a time
 *                      │
 *  network ─changeSettled─▶ session thread: snapshot, modules ─▶ Swing: NetworkDiff(editor, snapshot) ─▶ adopt
 *          ─valuesSampled─▶ LiveValuesRelay (texts, one hand-over queued at most) ─▶ GraphScene ─▶ canvas
 *          ─disconnected──▶ session ends; the editor stays open offline with the last state
 *
 *  collecting: edits stay here; DeployPreviewDialog lists NetworkDiff(base, editor) ─Apply all─▶ one apply
 * </pre>
 *
 * {@link org.fdnet.hi.live.RunningModulesPanel} loads, unloads, holds and resumes modules;
 * {@link org.fdnet.hi.live.InProcessRun} runs a network inside the editor ({@code fdnet hi --run FILE}).
 */
package org.fdnet.hi.live;

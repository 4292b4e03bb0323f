package org.fdnet.hi.edit;

import java.util.ArrayDeque;
import java.util.Deque;

/**
 * The undo and redo stacks of one editing session, and where the file was last saved. Each step keeps
 * the edit that takes it back (undo) or does it again (redo); applying one gives the other. Every step
 * has an id that follows it between the stacks, so the session is clean exactly when the step on top of
 * the undo stack is the one that was on top when the file was saved.
 */
final class EditHistory {
    record Step(long id, String label, ReversibleEdit edit) {
    }

    private final Deque<Step> undo = new ArrayDeque<>();
    private final Deque<Step> redo = new ArrayDeque<>();
    private long nextId = 1;
    private long savedAt;

    void done(String label, ReversibleEdit inverse) {
        undo.push(new Step(nextId++, label, inverse));
        redo.clear();
    }

    Step popUndo() {
        return undo.poll();
    }

    Step popRedo() {
        return redo.poll();
    }

    void pushUndo(Step step) {
        undo.push(step);
    }

    void pushRedo(Step step) {
        redo.push(step);
    }

    String undoLabel() {
        return undo.isEmpty() ? null : undo.peek().label();
    }

    String redoLabel() {
        return redo.isEmpty() ? null : redo.peek().label();
    }

    void markSaved() {
        savedAt = topId();
    }

    boolean dirty() {
        return topId() != savedAt;
    }

    private long topId() {
        return undo.isEmpty() ? 0 : undo.peek().id();
    }
}

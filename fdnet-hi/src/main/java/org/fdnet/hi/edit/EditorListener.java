package org.fdnet.hi.edit;

/** Told by {@link UndoableNetworkEditor} when its history or dirty state changes and when an edit is refused. */
public interface EditorListener {
    /** After every accepted edit, undo, redo or save: menus and the title re-read undo/redo/dirty. */
    void historyChanged();

    /** An edit, undo or redo was refused; nothing changed. */
    void refused(String reason);
}

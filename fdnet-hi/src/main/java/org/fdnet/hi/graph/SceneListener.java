package org.fdnet.hi.graph;

/** Told when what the graph shows changes: the canvas repaints, the information panel refreshes. */
public interface SceneListener {
    /** Positions, colours, visibility, highlight or the network itself changed. */
    void sceneChanged();

    /** The selected nodes or connection changed. */
    void selectionChanged();

    /** The live values drawn on the nodes changed (live mode); only the canvas cares. */
    default void valuesChanged() {
    }
}

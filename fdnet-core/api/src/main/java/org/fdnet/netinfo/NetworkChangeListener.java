package org.fdnet.netinfo;

/** Told of every completed change to a {@link NetworkInfo}: the editor's views listen here. */
@FunctionalInterface
public interface NetworkChangeListener {
    /**
     * An edit completed; called on the editing thread, after the model changed.
     *
     * @param change what changed
     */
    void networkChanged(NetworkChange change);
}

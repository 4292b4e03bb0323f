package org.fdnet.netinfo;

/** Told of every completed change to a {@link NetworkInfo}: the editor's views listen here. */
@FunctionalInterface
public interface NetworkChangeListener {
    void networkChanged(NetworkChange change);
}

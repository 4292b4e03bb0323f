package org.fdnet.hi.speedy;

/**
 * A component of a frame whose state only it changes: {@link #update()} recomputes its state from its parents'
 * (what the thesis calls asking a component to update itself). It never changes another component's state.
 */
@FunctionalInterface
public interface Updatable {
    void update();
}

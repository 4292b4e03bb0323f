package org.fdnet.hi.speedy;

/**
 * A component of a frame whose state only it changes: {@link #update()} recomputes its state from its parents'
 * (what the thesis calls asking a component to update itself). It never changes another component's state.
 */
@FunctionalInterface
public interface Updatable {
    void update();

    /**
     * A component with nothing to recompute: a user input whose state its setter sets, or a point that other
     * components hang from. A distinct instance on each call (a non-capturing lambda would be one shared object,
     * and the handler tells components apart by identity).
     */
    static Updatable marker() {
        return new Updatable() {
            @Override
            public void update() {
                // its state is set where it changes; nothing here derives from a parent
            }
        };
    }
}

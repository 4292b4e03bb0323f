package org.fdnet.hi.edit;

/**
 * One change to a network (and to the view state that follows names), able to say how to take itself back.
 * {@link #applyTo} looks at the model, changes it, and returns the edit that undoes exactly that change;
 * applying the returned edit returns in turn the edit that redoes it. A refused edit throws
 * {@link org.fdnet.netinfo.EditRefusedException} before changing anything.
 */
@FunctionalInterface
public interface ReversibleEdit {
    ReversibleEdit applyTo(EditTarget target);
}

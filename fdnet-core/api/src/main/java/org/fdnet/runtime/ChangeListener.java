package org.fdnet.runtime;

/** Told of every change request, executed or failed, after it settled (Ptolemy's change listener). */
@FunctionalInterface
public interface ChangeListener {
    void changeSettled(ChangeOutcome outcome);
}

package org.fdnet.runtime;

/** Told of every change request, executed or failed, after it settled (Ptolemy's change listener). */
@FunctionalInterface
public interface ChangeListener {
    /**
     * A change request settled; called on the thread that made the request, after the network changed (or did not).
     *
     * @param outcome what was asked and whether it was executed, with the reason when not
     */
    void changeSettled(ChangeOutcome outcome);
}

package org.fdnet.runtime;

/**
 * What happened to a change request: executed, or failed with the reason (the network is then exactly
 * as it was before the request).
 *
 * @param description what was asked, e.g. {@code unload module Legs}
 * @param executed    whether the change was made
 * @param reason      why it was refused, or null when executed
 */
public record ChangeOutcome(String description, boolean executed, String reason) {
    /**
     * An executed request.
     *
     * @param description what was asked
     * @return the outcome, without a reason
     */
    public static ChangeOutcome executed(String description) {
        return new ChangeOutcome(description, true, null);
    }

    /**
     * A refused request.
     *
     * @param description what was asked
     * @param reason      why it was refused, naming what is wrong
     * @return an outcome whose {@code executed} is false
     */
    public static ChangeOutcome failed(String description, String reason) {
        return new ChangeOutcome(description, false, reason);
    }

    @Override
    public String toString() {
        return executed ? description + ": executed" : description + ": failed: " + reason;
    }
}

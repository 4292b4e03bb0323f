package org.fdnet.runtime;

/**
 * What happened to a change request: executed, or failed with the reason (the network is then exactly
 * as it was before the request).
 */
public record ChangeOutcome(String description, boolean executed, String reason) {
    public static ChangeOutcome executed(String description) {
        return new ChangeOutcome(description, true, null);
    }

    public static ChangeOutcome failed(String description, String reason) {
        return new ChangeOutcome(description, false, reason);
    }

    @Override
    public String toString() {
        return executed ? description + ": executed" : description + ": failed: " + reason;
    }
}

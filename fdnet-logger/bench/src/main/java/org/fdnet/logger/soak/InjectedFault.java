package org.fdnet.logger.soak;

/**
 * A fault as it happened: injected at {@code atMillis}, over (the process back, the database up, the links clean or
 * healed) at {@code overMillis}, both epoch milliseconds; {@code healedMillis} is how long after the injection — after
 * the lift, for a network fault — a value acknowledged after it was stored end to end (-1: never).
 */
record InjectedFault(FaultKind kind, String target, long atMillis, long overMillis, long healedMillis) {
    /** Whether a value acknowledged at {@code ackMillis} may be lost or doubled by this fault: a host's kill -9 only. */
    boolean mayCost(long ackMillis, long marginMillis) {
        return kind == FaultKind.HOST_KILL && ackMillis >= atMillis - marginMillis && ackMillis <= overMillis + marginMillis;
    }

    InjectedFault healed(long millis) {
        return new InjectedFault(kind, target, atMillis, overMillis, millis);
    }
}

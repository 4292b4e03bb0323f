package org.fdnet.corba;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;

/**
 * Which certificate prepared each change a host holds between its two phases: only that certificate may commit or
 * abort it, so a member cannot execute or cancel a change another member was allowed to prepare.
 */
final class ChangeOwners {
    private final String hostName;
    private final Map<Long, String> preparedBy = new ConcurrentHashMap<>();

    ChangeOwners(String hostName) {
        this.hostName = hostName;
    }

    /** The caller prepared change {@code id}. */
    void prepared(long id) {
        preparedBy.put(id, Caller.name());
    }

    /**
     * Forgets change {@code id} when the caller prepared it (or nobody did here).
     *
     * @param what {@code commit} or {@code abort}, for the refusal
     * @throws org.omg.CORBA.NO_PERMISSION naming both certificates when another one prepared it
     */
    void settle(long id, String what) {
        String preparer = preparedBy.get(id);
        if (preparer != null && !preparer.equals(Caller.name())) {
            Caller.fail("certificate '" + Caller.name() + "' may not " + what + " change " + id + " on " + hostName
                    + ": certificate '" + preparer + "' prepared it");
        }
        preparedBy.remove(id);
    }
}

package org.fdnet.logger.server;

import java.util.HashMap;
import java.util.Map;
import org.fdnet.event.wire.ErrorCode;
import org.fdnet.logger.cache.RunProgress;

/**
 * Which receiver connection currently speaks for a run. A core that reconnects before the logger noticed
 * its old connection die takes the run over; the old connection is closed so two never feed one run.
 */
final class RunOwners {
    private final Map<RunProgress, ReceiverConnection> owners = new HashMap<>();

    void claim(RunProgress run, ReceiverConnection owner) {
        ReceiverConnection previous;
        synchronized (this) {
            previous = owners.put(run, owner);
        }
        if (previous != null && previous != owner) {
            previous.refuse(ErrorCode.REPLACED, "run " + run.uuid() + " reconnected on another connection");
        }
    }

    synchronized boolean owns(RunProgress run, ReceiverConnection c) {
        return owners.get(run) == c;
    }

    synchronized void release(RunProgress run, ReceiverConnection c) {
        owners.remove(run, c);
    }
}

package org.fdnet.corba;

import java.util.Objects;
import org.fdnet.event.RunIdentity;

/**
 * What every host of a deployment is told about the run before its share is created (and again when it comes back
 * or joins): it records its events as its part of {@code run}, with the logger at {@code loggerAddress}
 * ({@code HOST:PORT}; empty when only hosts with a logger of their own, {@code fdnet host --logger}, record); its
 * engine runs {@code workers} worker threads (0: the host's own default); and, when {@code traceCapacity} is above 0,
 * it keeps up to that many of its own events for the run's {@code --trace}.
 */
public record RunRecording(RunIdentity run, String loggerAddress, int workers, int traceCapacity) {
    public RunRecording {
        Objects.requireNonNull(run, "run");
        loggerAddress = loggerAddress == null ? "" : loggerAddress;
        if (workers < 0) {
            throw new IllegalArgumentException("workers must be at least 0 (0: each host's own), was " + workers);
        }
        if (traceCapacity < 0) {
            throw new IllegalArgumentException("traceCapacity must be at least 0 (0: no trace), was " + traceCapacity);
        }
    }

    /** Recorded only: each host keeps its own worker count, nothing is traced. */
    public RunRecording(RunIdentity run, String loggerAddress) {
        this(run, loggerAddress, 0, 0);
    }

    boolean traced() {
        return traceCapacity > 0;
    }
}

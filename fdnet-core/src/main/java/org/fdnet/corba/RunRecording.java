package org.fdnet.corba;

import java.util.Objects;
import org.fdnet.event.RunIdentity;

/**
 * How the hosts of a deployment record it: as parts of {@code run}, with the logger at {@code loggerAddress}
 * ({@code HOST:PORT}; empty when only hosts with a logger of their own, {@code fdnet host --logger}, record).
 */
public record RunRecording(RunIdentity run, String loggerAddress) {
    public RunRecording {
        Objects.requireNonNull(run, "run");
        loggerAddress = loggerAddress == null ? "" : loggerAddress;
    }
}

package org.fdnet.corba;

/** Chooses the engine behind a host: the one place that knows which {@link LocalNetwork} a host runs. */
public final class LocalNetworks {
    private LocalNetworks() {
    }

    /** The engine for host {@code hostName}. */
    public static LocalNetwork forHost(String hostName) {
        return new DataOnlyNetwork();
    }
}

package org.fdnet.logger.soak;

/**
 * The faults a soak injects; each kind of its plan at least once. The network kinds ({@link #network}) need hosts that
 * are apart ({@code fdnet soak --apart}): they are put on a host's link in an apart rig, silently — packets dropped or
 * slowed, never refused.
 */
enum FaultKind {
    LINK_FAULTS("cross-host calls dropped and delayed", false),
    HOST_KILL("kill -9 a host, then start it again", false),
    LOGGER_KILL("kill -9 the logger, then start it again", false),
    DATABASE_STOP("PostgreSQL stopped for 10 s", false),
    NAMING_RESTART("kill -9 the naming service, then start it again", false),
    HOST_PARTITION("a host's link black-holed, then healed", true),
    LOGGER_PARTITION("the logger's link black-holed (the hosts cannot reach it), then healed", true),
    NAMING_PARTITION("the naming service's link black-holed, then healed", true),
    LOSS("5 % of the packets on every host's link dropped at random", true),
    THROTTLE("a host's link throttled to 1 Mbit/s", true);

    final String description;
    final boolean network;

    FaultKind(String description, boolean network) {
        this.description = description;
        this.network = network;
    }
}

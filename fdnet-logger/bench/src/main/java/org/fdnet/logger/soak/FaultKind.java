package org.fdnet.logger.soak;

/** The faults a soak injects; each kind at least once per cycle. */
enum FaultKind {
    LINK_FAULTS("cross-host calls dropped and delayed"),
    HOST_KILL("kill -9 a host, then start it again"),
    LOGGER_KILL("kill -9 the logger, then start it again"),
    DATABASE_STOP("PostgreSQL stopped for 10 s"),
    NAMING_RESTART("kill -9 the naming service, then start it again");

    final String description;

    FaultKind(String description) {
        this.description = description;
    }
}

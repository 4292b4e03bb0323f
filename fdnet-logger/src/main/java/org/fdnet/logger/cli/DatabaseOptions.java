package org.fdnet.logger.cli;

import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;
import picocli.CommandLine.Option;

/** {@code --db URL} and {@code --db-user USER}: the commands that open the logger's database take them alike. */
public final class DatabaseOptions {
    @Option(names = "--db", paramLabel = "URL", description = "external database jdbc:postgresql://HOST:PORT/DB "
            + "(default: embedded PostgreSQL in ~/.fdnet/logger-db)")
    String db;

    @Option(names = "--db-user", paramLabel = "USER", description = "user for --db (default postgres)")
    String dbUser;

    /** Puts the options given into {@code config} (an external database when {@code --db} is given). */
    public LoggerConfig applyTo(LoggerConfig config) {
        if (db != null) {
            config.set(LoggerSetting.DATABASE_URL, db).set(LoggerSetting.DATABASE_EMBEDDED, "false");
        }
        if (dbUser != null) {
            config.set(LoggerSetting.DATABASE_USER, dbUser);
        }
        return config;
    }
}

package org.fdnet.logger.store;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.concurrent.TimeUnit;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * The embedded PostgreSQL makes commits durable: the library starts it with {@code -F} (fsync off), the
 * logger turns fsync back on unless {@code database.embeddedFsync=false} is asked for.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class EmbeddedDatabaseDurabilityTest {
    @TempDir
    Path folder;

    @Test
    void shouldRunTheLoggersDefaultEmbeddedDatabaseWithFsyncAndSynchronousCommitOn() throws Exception {
        LoggerConfig config = new LoggerConfig()
                .set(LoggerSetting.DATABASE_DIRECTORY, folder.resolve("db").toString())
                .set(LoggerSetting.RECEIVER_PORT, "0").set(LoggerSetting.SENDER_PORT, "0");
        try (NetworkStateLogger logger = new NetworkStateLogger(config)) {
            logger.start();
            assertThat(show(logger.store().target(), "fsync")).isEqualTo("on");
            assertThat(show(logger.store().target(), "synchronous_commit")).isEqualTo("on");
        }
    }

    @Test
    void shouldRunWithFsyncOffOnlyWhenAskedFor() throws Exception {
        try (EmbeddedDatabase db = EmbeddedDatabase.start(folder.resolve("throwaway"), 0, false)) {
            assertThat(show(db.target(), "fsync")).isEqualTo("off");
        }
        try (EmbeddedDatabase db = EmbeddedDatabase.startThrowaway(folder.resolve("bench"))) {
            assertThat(show(db.target(), "fsync")).isEqualTo("on");
        }
    }

    private static String show(DatabaseTarget target, String setting) throws SQLException {
        try (Connection c = target.open(); Statement s = c.createStatement();
             ResultSet rs = s.executeQuery("SHOW " + setting)) {
            rs.next();
            return rs.getString(1);
        }
    }
}

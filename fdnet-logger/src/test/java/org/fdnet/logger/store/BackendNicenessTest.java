package org.fdnet.logger.store;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import org.fdnet.logger.PostgresPerClass;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;

/** The writer's PostgreSQL backends run at {@code writer.backendNiceness}; other connections are left alone. */
class BackendNicenessTest {
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    @Test
    void shouldRunTheWritersBackendAtTheConfiguredNiceValue() throws Exception {
        try (EventStore store = new EventStore(database.fixture().target(), new QueryPriority(0), 15);
             Connection writer = store.openWriterConnection();
             Connection viewer = database.fixture().target().open()) {
            long server = parentOf(backendPid(viewer));
            assertThat(niceOf(server)).as("the server's own nice value (the test's)").isLessThan(15);
            assertThat(niceOf(backendPid(writer))).isEqualTo(15);
            assertThat(niceOf(backendPid(viewer))).as("a connection that is not the writer's").isEqualTo(niceOf(server));
        }
    }

    @Test
    void shouldLeaveTheBackendAloneAtZero() throws Exception {
        try (EventStore store = new EventStore(database.fixture().target(), new QueryPriority(0), 0);
             Connection writer = store.openWriterConnection()) {
            long pid = backendPid(writer);
            assertThat(niceOf(pid)).isEqualTo(niceOf(parentOf(pid)));
        }
    }

    @Test
    void shouldRefuseANiceValueOutsideZeroToNineteen() {
        assertThatThrownBy(() -> new LoggerConfig().set(LoggerSetting.WRITER_BACKEND_NICENESS, "20"))
                .hasMessage("writer.backendNiceness must be in [0, 19], was 20");
        assertThatThrownBy(() -> new LoggerConfig().set(LoggerSetting.WRITER_BACKEND_NICENESS, "-1"))
                .hasMessage("writer.backendNiceness must be in [0, 19], was -1");
    }

    private static long backendPid(Connection c) throws SQLException {
        try (Statement st = c.createStatement(); ResultSet rs = st.executeQuery("SELECT pg_backend_pid()")) {
            rs.next();
            return rs.getLong(1);
        }
    }

    private static int niceOf(long pid) throws IOException {
        return Integer.parseInt(statField(pid, 19));
    }

    /** A backend's parent is the server (postmaster), which runs at the nice value it was started with. */
    private static long parentOf(long pid) throws IOException {
        return Long.parseLong(statField(pid, 4));
    }

    /** Field {@code n} (1-based) of /proc/PID/stat, counted past the command name, which may hold spaces. */
    private static String statField(long pid, int n) throws IOException {
        String stat = Files.readString(Path.of("/proc/" + pid + "/stat"));
        return stat.substring(stat.lastIndexOf(')') + 2).split(" ")[n - 3];
    }
}

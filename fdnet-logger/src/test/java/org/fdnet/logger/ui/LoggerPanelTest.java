package org.fdnet.logger.ui;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import javax.swing.AbstractButton;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JTabbedPane;
import javax.swing.JTable;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.EventClock;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.ValueType;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.PostgresPerClass;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

/**
 * A live setting changed in the running panel, the panel's cache browser and <em>Retry database</em> button against a real PostgreSQL, stopped and started
 * again (the panel itself, in this JVM: no window is needed to press its buttons and read its table).
 */
@Timeout(value = 150, unit = TimeUnit.SECONDS)
class LoggerPanelTest {
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();
    @TempDir
    Path folder;

    @Test
    void shouldApplyALiveSettingBrowseCachedEventsAndRetryADatabaseReportedDownFromThePanel() throws Exception {
        LoggerConfig config = database.fixture().loggerConfig().set(LoggerSetting.WRITER_RECONNECT_ATTEMPTS, "2")
                .set(LoggerSetting.WRITER_RECONNECT_DELAY, "100").set(LoggerSetting.WRITER_CONNECTIONS, "1");
        LoggerPanel panel = onEdt(() -> new LoggerPanel(config, folder.resolve("logger.properties")));
        try {
            click(panel, "start");
            waitFor(() -> panel.logger() != null && panel.logger().running(), "logger started");
            NetworkStateLogger logger = panel.logger();
            onEdt(() -> {
                javax.swing.JTextField timeout = find(panel, LoggerSetting.WRITER_BATCH_TIMEOUT.key(), javax.swing.JTextField.class);
                timeout.setText("300");
                timeout.postActionEvent(); // Enter
                return null;
            });
            assertThat(logger.writer().settings().batchTimeoutMillis()).as("a live setting reaches the running writer")
                    .isEqualTo(300);
            assertThat(folder.resolve("logger.properties")).content().contains("writer.batchTimeoutMillis=300");
            assertThat(onEdt(() -> find(panel, LoggerSetting.WRITER_BATCH_SIZE.key(), javax.swing.JTextField.class)
                    .isEnabled())).as("a next-Start setting cannot be edited while running").isFalse();
            EventClock clock = new EventClock();
            try (LoggerClient core = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(),
                    "panel-core"))) {
                core.accept(new NodeNamedEvent(0, clock.next(), NodeKind.DATA, new NodeRef("main", "Speed")));
                core.accept(new NodeNamedEvent(1, clock.next(), NodeKind.DATA, new NodeRef("main", "Angle")));
                send(core, clock, 0, 50);
                assertThat(core.flush(30_000)).as("first values committed").isTrue();
                int speed = logger.directory().nodes("main/Speed").get(0).sourceId();
                // A viewer monitoring Speed that has not sent anything yet: Speed's next values stay cached.
                logger.cache().subscribe(e -> { }, new int[] {speed});
                send(core, clock, 0, 10);
                assertThat(core.flush(30_000)).as("monitored values committed").isTrue();

                database.fixture().stopDatabase();
                send(core, clock, 1, 20);
                waitFor(() -> find(panel, "retry", AbstractButton.class).isEnabled(), "Retry enabled once DOWN");
                assertThat(logger.writer().databaseState()).startsWith("DOWN");

                onEdt(() -> {
                    find(panel, "tabs", JTabbedPane.class).setSelectedIndex(5); // Cache: refreshes
                    return null;
                });
                pick(panel, "main/Speed");
                JTable table = find(panel, "cacheEvents", JTable.class);
                assertThat(rows(table, 3)).as("Speed's cached values: written and monitored").hasSize(10)
                        .allMatch("true true"::equals);
                pick(panel, "main/Angle");
                assertThat(rows(table, 3)).as("Angle's cached values: neither written nor monitored").hasSize(20)
                        .allMatch("false false"::equals);
                assertThat(onEdt(() -> find(panel, "cacheSummary", JLabel.class).getText()))
                        .contains("main/Angle: 20 events in the cache, 0 written, 20 not yet written, 0 monitored");

                database.fixture().startDatabase();
                click(panel, "retry");
                waitFor(() -> logger.writer().databaseState().equals("connected"), "database connected again");
                assertThat(core.flush(60_000)).as("values held while DOWN committed after the retry").isTrue();
                onEdt(() -> {
                    find(panel, "cacheRefresh", AbstractButton.class).doClick();
                    return null;
                });
                assertThat(rows(table, 3)).as("Angle's values written and, unmonitored, gone from the cache").isEmpty();
                assertThat(database.fixture().count("SELECT count(*) FROM datavalue_log WHERE sourceid = "
                        + logger.directory().nodes("main/Angle").get(0).sourceId())).isEqualTo(20);
            }
        } finally {
            onEdt(() -> {
                panel.dispose();
                return null;
            });
        }
    }

    private static void send(LoggerClient core, EventClock clock, int localId, int n) {
        for (int i = 0; i < n; i++) {
            core.accept(new DataValueEvent(localId, clock.next(), ValueType.DOUBLE, Double.toString(i)));
        }
    }

    private static void pick(LoggerPanel panel, String node) throws Exception {
        onEdt(() -> {
            JComboBox<?> picker = find(panel, "cacheNode", JComboBox.class);
            find(panel, "cacheRefresh", AbstractButton.class).doClick();
            for (int i = 0; i < picker.getItemCount(); i++) {
                if (picker.getItemAt(i).toString().startsWith(node + " ")) {
                    picker.setSelectedIndex(i);
                    return null;
                }
            }
            throw new AssertionError("no " + node + " in the cache browser's picker");
        });
    }

    /** Each row's columns 2.. as "written monitored". */
    private static java.util.List<String> rows(JTable table, int lastColumn) throws Exception {
        return onEdt(() -> {
            java.util.List<String> out = new java.util.ArrayList<>();
            for (int r = 0; r < table.getRowCount(); r++) {
                out.add(table.getValueAt(r, lastColumn - 1) + " " + table.getValueAt(r, lastColumn));
            }
            return out;
        });
    }

    private static void click(LoggerPanel panel, String button) throws Exception {
        onEdt(() -> {
            find(panel, button, AbstractButton.class).doClick();
            return null;
        });
    }

    private static <T extends java.awt.Component> T find(LoggerPanel panel, String name, Class<T> type) {
        return ConfigPanelScenario.find(panel, name, type);
    }

    private static void waitFor(Callable<Boolean> condition, String what) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (!onEdt(condition)) {
            assertThat(System.nanoTime()).as("waiting for: " + what).isLessThan(deadline);
            Thread.sleep(50);
        }
    }

    private static <T> T onEdt(Callable<T> c) throws Exception {
        return ConfigPanelScenario.onEdt(c);
    }
}

package org.fdnet.logger;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.event.client.ViewerClient;
import org.fdnet.event.wire.LoggedNode;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

@Timeout(value = 120, unit = TimeUnit.SECONDS)
class LoggerEndToEndTest {
    @TempDir
    static Path folder;
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    @Test
    void shouldStoreEveryEventOfARunExactlyOnceAndNameItsNodes() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig())) {
            logger.start();
            TestEvents core = new TestEvents(5);
            try (LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(),
                    "test-core").withJournal(folder.resolve("journal1"), 1 << 20).withMemoryEvents(1000))) {
                core.name(client);
                for (int i = 0; i < 20_000; i++) {
                    core.produce(client);
                }
                assertThat(client.flush(60_000)).isTrue();
                assertThat(client.lostEvents()).isZero();
            }
            long rows = database.fixture().count("SELECT count(*) FROM datavalue_log") + database.fixture().count("SELECT count(*) FROM procvalue_log")
                    + database.fixture().count("SELECT count(*) FROM netcommand_log");
            assertThat(rows).isEqualTo(20_000);
            assertThat(database.fixture().count("SELECT count(*) FROM fdnet_node WHERE module = 'arm'")).isEqualTo(6);
            assertThat(database.fixture().count("SELECT count(*) FROM datavalue_log WHERE value = E'line\\\\one\\nline two\u00e9'"))
                    .isGreaterThan(0);
            assertThat(database.fixture().count("SELECT count(*) FROM fdnet_run")).isEqualTo(1);
        }
    }

    @Test
    void shouldAnswerHistoryInTimeOrderFromCacheAndDatabaseAndStreamMonitoredNodes() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig())) {
            logger.start();
            TestEvents core = new TestEvents(3);
            List<NetworkEvent> live = new CopyOnWriteArrayList<>();
            try (LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(),
                    "history-core").withJournal(folder.resolve("journal2"), 1 << 20));
                 ViewerClient viewer = new ViewerClient("127.0.0.1", logger.senderPort(), "viewer", live::add)) {
                core.name(client);
                for (int i = 0; i < 3000; i++) {
                    core.produce(client);
                }
                assertThat(client.flush(30_000)).isTrue();
                List<LoggedNode> joints = viewer.nodes("arm/Joint1");
                assertThat(joints).isNotEmpty(); // newest run first (the class shares one database)
                int joint = joints.get(0).sourceId();
                viewer.monitor(joint);
                Thread.sleep(200);
                for (int i = 0; i < 3000; i++) {
                    core.produce(client);
                }
                assertThat(client.flush(30_000)).isTrue();
                List<NetworkEvent> history = viewer.history(new int[] {joint}, 0, Long.MAX_VALUE);
                List<NetworkEvent> values = new ArrayList<>(history);
                assertThat(values).allMatch(e -> e instanceof DataValueEvent && e.sourceId() == joint);
                assertThat(values).hasSizeGreaterThan(1500);
                for (int i = 1; i < values.size(); i++) {
                    assertThat(values.get(i).time()).isGreaterThan(values.get(i - 1).time());
                }
                long deadline = System.currentTimeMillis() + 10_000;
                while (live.size() < 900 && System.currentTimeMillis() < deadline) {
                    Thread.sleep(50);
                }
                assertThat(live).isNotEmpty().allMatch(e -> e.sourceId() == joint);
                assertThat(history).containsAll(live);
                long stored = database.fixture().count("SELECT count(*) FROM datavalue_log WHERE sourceid = " + joint);
                assertThat((long) values.size()).isEqualTo(stored);
            }
        }
    }
}

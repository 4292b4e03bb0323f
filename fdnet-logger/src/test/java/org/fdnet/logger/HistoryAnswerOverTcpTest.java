package org.fdnet.logger;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.TypedValue;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.event.client.ViewerClient;
import org.fdnet.event.wire.EventCodec;
import org.fdnet.event.wire.FrameWriter;
import org.fdnet.event.wire.HistoryColumns;
import org.fdnet.event.wire.MessageType;
import org.fdnet.logger.cache.CachedEvent;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.cache.MonitorSubscriber;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

/**
 * A viewer's history over TCP from a real logger: the columns answer holds exactly the events of the event
 * answer (numbers in binary), from the cache and from cache and database merged (the database's text read back
 * to exactly the values sent).
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class HistoryAnswerOverTcpTest {
    @TempDir
    static Path folder;
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    @Test
    void shouldAnswerColumnsHoldingTheSameEventsFromCacheAndDatabase() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig())) {
            logger.start();
            TestEvents core = new TestEvents(3);
            try (LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(),
                    "columns-core").withJournal(folder.resolve("journal"), 1 << 20));
                 ViewerClient viewer = new ViewerClient("127.0.0.1", logger.senderPort(), "viewer", e -> { })) {
                core.name(client);
                for (int i = 0; i < 2000; i++) {
                    core.produce(client);
                }
                assertThat(client.flush(30_000)).isTrue();
                int joint = viewer.nodes("arm/Joint1").get(0).sourceId();
                int controller = viewer.nodes("arm/Controller").get(0).sourceId();
                EventCache cache = logger.cache();
                List<CachedEvent> held = new CopyOnWriteArrayList<>();
                MonitorSubscriber plot = held::add; // a plot that keeps its node's events in memory
                cache.subscribe(plot, new int[] {joint});
                for (int i = 0; i < 3000; i++) {
                    core.produce(client);
                }
                assertThat(client.flush(30_000)).isTrue();
                assertThat(held).hasSizeGreaterThan(900);
                long from = held.get(0).time();

                // from the cache alone: the same events, numbers as numbers
                List<NetworkEvent> events = viewer.history(new int[] {joint}, from, Long.MAX_VALUE);
                HistoryColumns columns = viewer.historyColumns(new int[] {joint}, from, Long.MAX_VALUE);
                assertThat(events).hasSize(held.size()).isEqualTo(held.stream().map(CachedEvent::event).toList());
                assertThat(columns.events()).isEqualTo(events);
                for (int i = 0; i < columns.size(); i++) {
                    TypedValue value = ((DataValueEvent) events.get(i)).value();
                    assertThat(columns.hasNumber(i)).isEqualTo(value.isNumber());
                    if (columns.hasNumber(i)) {
                        assertThat(columns.number(i)).isEqualTo(value.number());
                    }
                }
                assertThat(viewer.historyColumns(new int[] {joint}, from, Long.MAX_VALUE).events()).isEqualTo(events);

                // the whole run: earlier events left memory, so cache and database merged
                List<NetworkEvent> all = viewer.history(new int[] {joint}, 0, Long.MAX_VALUE);
                assertThat(all).hasSizeGreaterThan(held.size());
                assertThat((long) all.size()).isEqualTo(
                        database.fixture().count("SELECT count(*) FROM datavalue_log WHERE sourceid = " + joint));
                assertThat(viewer.historyColumns(new int[] {joint}, 0, Long.MAX_VALUE).events()).isEqualTo(all);

                // two nodes, values, statuses and commands, merged in time order
                List<NetworkEvent> both = viewer.history(new int[] {joint, controller}, from, Long.MAX_VALUE);
                assertThat(both).anyMatch(e -> e.sourceId() == controller).anyMatch(e -> e.sourceId() == joint);
                assertThat(viewer.historyColumns(new int[] {joint, controller}, from, Long.MAX_VALUE).events())
                        .isEqualTo(both);
                cache.unsubscribe(plot, new int[] {joint}, held);
            }
        }
    }
}

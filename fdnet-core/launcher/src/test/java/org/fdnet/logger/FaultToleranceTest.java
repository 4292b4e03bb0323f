package org.fdnet.logger;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.io.StringReader;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.logger.cli.LoggerPrompt;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.logger.server.ConnectionState;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;

/** Real faults while a core keeps producing: nothing lost, nothing stored twice. */
@Timeout(value = 180, unit = TimeUnit.SECONDS)
class FaultToleranceTest {
    @TempDir
    static Path folder;
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    private static long storedEvents(int runId) throws Exception {
        String ofRun = " WHERE sourceid IN (SELECT sourceid FROM fdnet_node WHERE run_id = " + runId + ")";
        return database.fixture().count("SELECT count(*) FROM datavalue_log" + ofRun) + database.fixture().count("SELECT count(*) FROM procvalue_log" + ofRun)
                + database.fixture().count("SELECT count(*) FROM netcommand_log" + ofRun);
    }

    private static int runOf(LoggerClient client) throws Exception {
        return (int) database.fixture().count("SELECT run_id FROM fdnet_run WHERE run_uuid = '" + client.run() + "'");
    }

    @Test
    void shouldStoreEveryEventExactlyOnceWhenTheDatabaseStopsMidStreamAndComesBack() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig())) {
            logger.start();
            try (LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(),
                    "outage-core").withJournal(folder.resolve("j-outage"), 64 << 20))) {
                Producer producer = new Producer(new TestEvents(8), client, 20);
                Thread.sleep(1500);
                database.fixture().stopDatabase();
                Thread.sleep(2500);
                assertThat(logger.writer().databaseState()).startsWith("lost");
                database.fixture().startDatabase();
                Thread.sleep(1000);
                long produced = producer.stop();
                assertThat(client.flush(90_000)).isTrue();
                assertThat(client.lostEvents()).isZero();
                assertThat(storedEvents(runOf(client))).isEqualTo(produced);
                assertThat(logger.writer().databaseState()).isEqualTo("connected");
            }
        }
    }

    @Test
    void shouldReportTheDatabaseDownAfterItsReconnectionAttemptsAndRetryOnlyWhenToldAtThePrompt() throws Exception {
        LoggerConfig config = database.fixture().loggerConfig().set(LoggerSetting.WRITER_RECONNECT_ATTEMPTS, "3")
                .set(LoggerSetting.WRITER_RECONNECT_DELAY, "100").set(LoggerSetting.WRITER_CONNECTIONS, "1");
        try (NetworkStateLogger logger = new NetworkStateLogger(config)) {
            logger.start();
            try (LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(),
                    "attempts-core").withJournal(folder.resolve("j-attempts"), 64 << 20))) {
                Producer producer = new Producer(new TestEvents(8), client, 20);
                waitForCommits(client, 500);
                database.fixture().stopDatabase();
                long deadline = System.currentTimeMillis() + 60_000;
                while (!logger.writer().databaseState().startsWith("DOWN")) {
                    assertThat(System.currentTimeMillis()).as(logger.writer().databaseState()).isLessThan(deadline);
                    Thread.sleep(50);
                }
                // "Number of attempts" 3: three reconnections after the write that lost the database.
                assertThat(logger.writer().databaseState()).contains(", 3 reconnection attempts; not retrying until told to");
                assertThat(logger.writer().reconnectionAttempts()).isEqualTo(3);
                // Down means no more attempts, even once the database is back: ten delays later still 3.
                database.fixture().startDatabase();
                Thread.sleep(1000);
                assertThat(logger.writer().databaseState()).contains(", 3 reconnection attempts; not retrying until told to");
                assertThat(logger.writer().reconnectionAttempts()).isEqualTo(3);
                assertThat(client.lostEvents()).isZero();

                // The headless logger's prompt: `retry` on its standard input (no SIGHUP).
                ByteArrayOutputStream answers = new ByteArrayOutputStream();
                new LoggerPrompt(logger, new BufferedReader(new StringReader("retry\n")),
                        new PrintStream(answers, true, StandardCharsets.UTF_8)).run();
                assertThat(answers.toString(StandardCharsets.UTF_8)).contains("retrying the database (was: DOWN since");
                long produced = producer.stop();
                assertThat(client.flush(90_000)).isTrue();
                assertThat(client.lostEvents()).isZero();
                assertThat(storedEvents(runOf(client))).isEqualTo(produced);
                assertThat(logger.writer().databaseState()).isEqualTo("connected");
            }
        }
    }

    @Test
    void shouldStopTheLoggerAtTheFirstLossWithoutReconnectAndLetTheNextLoggerStoreEverything() throws Exception {
        int receiver = freePort();
        LoggerConfig config = database.fixture().loggerConfig().set(LoggerSetting.WRITER_RECONNECT, "false")
                .set(LoggerSetting.RECEIVER_PORT, Integer.toString(receiver));
        try (LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", receiver,
                "no-reconnect-core").withJournal(folder.resolve("j-no-reconnect"), 64 << 20))) {
            Producer producer;
            try (NetworkStateLogger first = new NetworkStateLogger(config)) {
                first.start();
                producer = new Producer(new TestEvents(8), client, 20);
                waitForCommits(client, 500);
                database.fixture().stopDatabase();
                long deadline = System.currentTimeMillis() + 60_000;
                while (first.running()) {
                    assertThat(System.currentTimeMillis()).as("the logger gives up").isLessThan(deadline);
                    Thread.sleep(50);
                }
                assertThat(first.writer().databaseState()).contains("0 reconnection attempts");
            }
            database.fixture().startDatabase();
            try (NetworkStateLogger second = new NetworkStateLogger(config)) {
                second.start();
                long produced = producer.stop();
                assertThat(client.flush(90_000)).isTrue();
                assertThat(client.lostEvents()).isZero();
                assertThat(storedEvents(runOf(client))).isEqualTo(produced);
            }
        }
    }

    @Test
    void shouldPushBackOnTheCoreWithinItsCapacityWhileTheDatabaseIsDownAndLoseNothing() throws Exception {
        LoggerConfig config = database.fixture().loggerConfig().set(LoggerSetting.MEMORY_CAPACITY_MB, "1");
        long capacity = config.cacheCapacityBytes();
        // The client's window (events it sends unacknowledged) must hold more than the cache's capacity, or the
        // database's outage could never press the cache: 8,000 events of ~175 counted bytes are 1.3 MiB.
        int window = 8000;
        assertThat((long) window * config.networkEventBytes()).isGreaterThan(capacity);
        try (NetworkStateLogger logger = new NetworkStateLogger(config)) {
            logger.start();
            try (LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(),
                    "pressed-core").withMemoryEvents(window).withJournal(folder.resolve("j-press"), 256 << 20))) {
                Producer producer = new Producer(new TestEvents(8), client, 40);
                waitForCommits(client, 1000);
                database.fixture().stopDatabase();
                long maxUsed = 0;
                boolean sawPressure = false;
                boolean sawWaitingCore = false;
                long deadline = System.currentTimeMillis() + 4000;
                while (System.currentTimeMillis() < deadline) {
                    LoggerStatus s = logger.status();
                    maxUsed = Math.max(maxUsed, s.cache().usedBytes());
                    sawPressure |= s.cache().pressured();
                    sawWaitingCore |= s.cores().stream().anyMatch(c -> c.state() == ConnectionState.WAITING);
                    Thread.sleep(20);
                }
                assertThat(sawPressure).as("critical level reached").isTrue();
                assertThat(sawWaitingCore).as("receiver stopped reading its core").isTrue();
                assertThat(maxUsed).as("cache within its capacity").isLessThanOrEqualTo(capacity);
                assertThat(client.status().inJournal()).as("the core spilled to its journal, never blocked").isPositive();
                database.fixture().startDatabase();
                long produced = producer.stop();
                assertThat(client.flush(120_000)).isTrue();
                assertThat(client.lostEvents()).isZero();
                assertThat(storedEvents(runOf(client))).isEqualTo(produced);
            }
        }
    }

    @Test
    void shouldStoreEveryEventExactlyOnceWhenTheLoggerProcessIsKilledAndRestarted() throws Exception {
        int receiver = freePort();
        int sender = freePort();
        Process logger = startLoggerProcess(receiver, sender, "1");
        try (LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", receiver, "kill-core")
                .withJournal(folder.resolve("j-kill"), 64 << 20))) {
            Producer producer = new Producer(new TestEvents(6), client, 20);
            waitForCommits(client, 2000);
            logger.destroyForcibly().waitFor(10, TimeUnit.SECONDS); // SIGKILL: no drain, no goodbye
            Thread.sleep(1500);
            logger = startLoggerProcess(receiver, sender, "2");
            Thread.sleep(2000);
            long produced = producer.stop();
            assertThat(client.flush(90_000)).isTrue();
            assertThat(client.lostEvents()).isZero();
            assertThat(storedEvents(runOf(client))).isEqualTo(produced);
        } finally {
            logger.destroy();
            if (!logger.waitFor(30, TimeUnit.SECONDS)) {
                logger.destroyForcibly();
            }
        }
    }

    private static void waitForCommits(LoggerClient client, long atLeast) throws InterruptedException {
        long deadline = System.currentTimeMillis() + 30_000;
        while (client.status().acked() < atLeast && System.currentTimeMillis() < deadline) {
            Thread.sleep(20);
        }
        assertThat(client.status().acked()).isGreaterThanOrEqualTo(atLeast);
    }

    static int freePort() throws IOException {
        try (ServerSocket s = new ServerSocket(0)) {
            return s.getLocalPort();
        }
    }

    private static Process startLoggerProcess(int receiver, int sender, String tag) throws Exception {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-cp", System.getProperty("java.class.path"), "org.fdnet.cli.FdnetCommand", "logger",
                "--db", database.fixture().target().url(), "--receiver-port", Integer.toString(receiver),
                "--sender-port", Integer.toString(sender), "--config", folder.resolve("none.properties").toString(),
                "--status-every", "1"));
        Process p = new ProcessBuilder(cmd).redirectErrorStream(true)
                .redirectOutput(folder.resolve("logger-" + tag + ".log").toFile()).start();
        long deadline = System.currentTimeMillis() + 30_000;
        while (System.currentTimeMillis() < deadline) {
            try (Socket s = new Socket("127.0.0.1", receiver)) {
                return p;
            } catch (IOException e) {
                if (!p.isAlive()) {
                    throw new IllegalStateException("logger process exited: "
                            + java.nio.file.Files.readString(folder.resolve("logger-" + tag + ".log")));
                }
                Thread.sleep(100);
            }
        }
        p.destroyForcibly();
        throw new IllegalStateException("logger process did not listen on " + receiver);
    }
}

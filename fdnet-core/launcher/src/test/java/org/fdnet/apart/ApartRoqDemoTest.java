package org.fdnet.apart;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.logger.store.EmbeddedDatabase;
import org.fdnet.tls.KeyMaker;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * RoQ's real-time loop on a host of its own (the apart rig: a network namespace each, over mutual TLS), recording
 * with {@code fdnet logger} on another, while the logger is black-holed for 10 s in the middle of the walk (a silent
 * partition: packets dropped, no reset). The demo feeds the simulator's snapshots to the network on its bridge
 * thread, and every commit hands its events to the logger client; the client must hold them (in memory, then its
 * journal) and never make a commit wait for the logger. Asserted: the longest gap between two snapshots fed stays
 * below the logger client's silence timeout (the longest any wait on the logger may last), the run ends normally
 * with no fall, every event the logger acknowledged is in its database exactly once, and the values RoQ's network
 * committed while the logger was unreachable are there with no hole: the client took the logger's silence for a
 * partition, and nothing it sent could pass before the heal, so those values were all resent after it.
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class ApartRoqDemoTest {
    private static final String NETWORK = Path.of("../../networks/roq-walk.fdn").toAbsolutePath().normalize()
            .toString();
    private static final int RECEIVER_PORT = 5555;
    private static final int SENDER_PORT = 5556;
    private static final long READY_MILLIS = 60_000;
    private static final long WALK_BEFORE_MILLIS = 4_000;
    private static final long BLACK_HOLE_MILLIS = 10_000;
    /** The longest any wait on the logger may hold a caller: the logger client's silence timeout (5 s). */
    private static final long BOUND_MILLIS = LoggerClientSettings.DEFAULT_SILENCE_TIMEOUT.toMillis();
    /** Values of a walking RoQ are committed every few milliseconds; a hole this long in the outage is a loss. */
    private static final long HOLE_MICROS = 1_000_000;
    private static final Pattern FED = Pattern.compile("^network: ([\\d,]+) snapshots fed, longest gap between two"
            + " ([\\d.]+) ms \\(until t=(-?[\\d.]+) s\\)$");
    private static final Pattern COMMITTED = Pattern.compile("^logger: ([\\d,]+) of ([\\d,]+) events of run"
            + " ([0-9a-f-]{36}) committed to the logger at \\S+, ([\\d,]+) lost$");
    private static final Pattern SUMMARY = Pattern.compile("^summary: walked (-?[\\d.]+) m in ([\\d.]+) s, no fall");
    private static final Pattern LOOP = Pattern.compile("^loop: .*");
    /** The logger client's warning when the logger has been silent for its silence timeout. */
    private static final Pattern SILENT = Pattern.compile("logger at \\S+ silent for (\\d+) ms \\(partitioned\\?\\)");

    @TempDir
    Path folder;

    private ApartProcesses apart;

    @AfterEach
    void cleanUp() {
        if (apart != null) {
            apart.close();
        }
    }

    @Test
    void shouldKeepRoqsLoopInRhythmAndStoreEveryAcknowledgedEventOnceWhenItsLoggerIsBlackHoled() throws Exception {
        apart = ApartProcesses.create("fdnaproq", List.of("roq", "logger"), folder.resolve("home"));
        KeyMaker keys = new KeyMaker(folder.resolve("keys"));
        keys.make(List.of("roq", "logger"));
        Files.writeString(folder.resolve("logger.properties"), "database.embeddedDirectory=" + folder.resolve("pg")
                + "\nwriter.batchTimeoutMillis=200\n");
        FdnetChildProcess logger = start("logger", "logger", List.of("logger", "--bind", address("logger"),
                "--receiver-port", Integer.toString(RECEIVER_PORT), "--sender-port", Integer.toString(SENDER_PORT),
                "--config", folder.resolve("logger.properties").toString(), "--tls", keys.store("logger").toString()),
                "fdnet logger: cores -> ");
        long runSeconds = (WALK_BEFORE_MILLIS + BLACK_HOLE_MILLIS) / 1000 + 8;
        FdnetChildProcess demo = start("demo", "roq", List.of("demo", "--for", runSeconds + "s", "--network", NETWORK,
                "--course", "flat", "--no-control", "--logger", address("logger") + ":" + RECEIVER_PORT, "--tls",
                keys.store("roq").toString()), "recording with the logger at");

        Thread.sleep(WALK_BEFORE_MILLIS);
        long cutMicros = System.currentTimeMillis() * 1000;
        apart.rig().blackhole("logger");
        try {
            Thread.sleep(BLACK_HOLE_MILLIS);
        } finally {
            apart.rig().heal("logger");
        }
        long healMicros = System.currentTimeMillis() * 1000;

        assertThat(demo.awaitExit(60_000)).as("the demo ends normally, no fall:\n%s", output(demo)).isZero();
        Matcher summary = line(demo, SUMMARY);
        Matcher fed = line(demo, FED);
        double longestGapMillis = Double.parseDouble(fed.group(2));
        assertThat(longestGapMillis).as("the longest gap between two snapshots fed to RoQ's network, ms (bound: the"
                + " logger client's silence timeout):\n%s", output(demo)).isLessThan(BOUND_MILLIS);
        String silent = line(demo, SILENT).group(); // the logger client noticed the black hole
        Matcher committed = line(demo, COMMITTED);
        long acked = count(committed.group(1));
        assertThat(count(committed.group(4))).as("events lost:\n%s", output(demo)).isZero();
        assertThat(acked).as("every event the client accepted was acknowledged").isEqualTo(count(committed.group(2)))
                .isPositive();
        logger.stop(60_000);

        long carried;
        long hole;
        long rows;
        try (EmbeddedDatabase database = EmbeddedDatabase.start(folder.resolve("pg"), 0)) {
            DatabaseTarget target = database.target();
            String run = committed.group(3);
            rows = LoggedRows.rowsOf(target, run);
            carried = LoggedRows.valuesBetween(target, run, cutMicros, healMicros);
            hole = LoggedRows.longestGapMicros(target, run, cutMicros, healMicros);
        }
        System.out.printf(Locale.ROOT, "ApartRoqDemoTest: %s; logger black-holed %.1f s (%s); longest gap between"
                        + " two snapshots fed %.1f ms, until t=%s s (bound %d ms); %s; %,d events acknowledged,"
                        + " %,d rows; %,d values committed during the black hole stored, longest hole %.1f ms%n",
                summary.group(0),
                (healMicros - cutMicros) / 1e6, silent, longestGapMillis, fed.group(3), BOUND_MILLIS,
                line(demo, LOOP).group(), acked, rows, carried, hole / 1e3);
        assertThat(rows).as("every acknowledged event in the database exactly once").isEqualTo(acked);
        assertThat(carried).as("values RoQ's network committed while the logger was black-holed").isPositive();
        assertThat(hole).as("the longest time between two stored values of the black hole, µs")
                .isLessThan(HOLE_MICROS);
    }

    private FdnetChildProcess start(String label, String host, List<String> args, String ready) {
        return apart.start(label, host, args, ready, READY_MILLIS);
    }

    private String address(String host) {
        return apart.address(host);
    }

    private static Matcher line(FdnetChildProcess p, Pattern pattern) {
        return p.output().stream().map(pattern::matcher).filter(Matcher::find).findFirst()
                .orElseThrow(() -> new AssertionError("no line " + pattern + " in:\n" + output(p)));
    }

    private static String output(FdnetChildProcess p) {
        return String.join("\n", p.output());
    }

    private static long count(String digits) {
        return Long.parseLong(digits.replace(",", ""));
    }
}

package org.fdnet.logger;

import static org.assertj.core.api.Assertions.assertThat;

import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.corba.OrbSettings;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/**
 * {@code networks/two-robots.fdn} over three FDNet processes (hosts {@code flyer} and {@code crawler}, and
 * {@code fdnet run} as host {@code operator-station}) with the logger on a real PostgreSQL: every host records
 * its own events, and a host killed with {@code kill -9} and started again records again, with nothing it had
 * committed lost or stored twice.
 */
@Timeout(value = 240, unit = TimeUnit.SECONDS)
class DistributedRunWithLoggerTest {
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    private static final Pattern COMMITTED = Pattern.compile("logger: all ([\\d,]+) events of run ([0-9a-f-]{36}) committed");

    private final List<FdnetChildProcess> processes = new ArrayList<>();

    @AfterEach
    void stopEveryProcess() {
        for (int i = processes.size() - 1; i >= 0; i--) {
            processes.get(i).close();
        }
    }

    @Test
    void shouldStoreEveryValueOfEveryHostAndKeepWhatAKilledHostHadCommitted() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig())) {
            logger.start();
            String loggerAddress = "127.0.0.1:" + logger.receiverPort();
            int namingPort = FdnetChildProcess.freePort();
            start("naming", List.of("naming", "--port", Integer.toString(namingPort)), "fdnet naming ready");
            String naming = OrbSettings.namingCorbaloc(OrbSettings.LOOPBACK, namingPort);
            // The flyer names its logger itself; the crawler gets the address fdnet run --logger hands over.
            FdnetChildProcess flyer = start("host flyer",
                    List.of("host", "--name", "flyer", "--naming", naming, "--logger", loggerAddress), "fdnet host flyer ready");
            List<String> crawlerArgs = List.of("host", "--name", "crawler", "--naming", naming);
            FdnetChildProcess firstCrawler = start("host crawler", crawlerArgs, "fdnet host crawler ready");
            FdnetChildProcess run = start("run two-robots", List.of("run", "../../networks/two-robots.fdn", "--naming", naming,
                    "--as", "operator-station", "--for", "30s", "--logger", loggerAddress), "running on 3 hosts");

            awaitLine(run, l -> l.startsWith("[operator]") && !l.endsWith("main/Certainty=0.0000"));
            String firstCrawlerRun = awaitCrawlerValuesCommitted();
            firstCrawler.kill();
            FdnetChildProcess secondCrawler = start("host crawler again", crawlerArgs, "fdnet host crawler ready");
            awaitLine(run, l -> l.contains("host crawler is back"));

            assertThat(run.awaitExit(120_000)).as(String.join("\n", run.output())).isZero();
            flyer.stop(60_000);
            secondCrawler.stop(60_000);

            String flyerRun = committedRun(flyer, "flyer");
            String secondCrawlerRun = committedRun(secondCrawler, "crawler");
            String operatorRun = committedRun(run, "operator-station");
            assertThat(List.of(flyerRun, secondCrawlerRun, operatorRun, firstCrawlerRun)).doesNotHaveDuplicates();

            // Every value each host wrote is stored once: the rows of its run are exactly what it says it committed.
            assertThat(rowsOf(flyerRun)).isEqualTo(reportedCount(flyer));
            assertThat(rowsOf(secondCrawlerRun)).isEqualTo(reportedCount(secondCrawler));
            assertThat(rowsOf(operatorRun)).isEqualTo(reportedCount(run, "host operator-station: "));
            // ... and each host's Datas are among them, each value once, in its Data's order (one time each).
            assertValuesStoredOnceInOrder(flyerRun, "Map");
            for (String crawlerRun : List.of(firstCrawlerRun, secondCrawlerRun)) {
                assertValuesStoredOnceInOrder(crawlerRun, "Heading");
                assertValuesStoredOnceInOrder(crawlerRun, "Certainty");
            }
            // The killed crawler's first life is still in the database: what it had committed was kept.
            assertThat(database.fixture().count("SELECT count(*) FROM fdnet_run WHERE core_name = 'fdnet host crawler'"))
                    .isEqualTo(2);
            // Node ids are unique across hosts and runs: one row per (run, node) and no id shared.
            assertThat(database.fixture().count("SELECT count(*) FROM fdnet_node WHERE node = 'Heading'"))
                    .isGreaterThanOrEqualTo(2); // both lives of the crawler
            assertThat(database.fixture().count("SELECT count(*) - count(DISTINCT sourceid) FROM fdnet_node")).isZero();
        }
    }

    /**
     * What a distributed run leaves in the database: one network run in the database, its three hosts as three streams filed under it, each
     * Data once (on its home host; no stand-in of it anywhere), every stream's rows exactly what its host says the
     * logger committed, and every Data's values stored once each, in the order its home host wrote them. To make
     * that order checkable each value must say where it stands, so {@code --param} gives the three Relations
     * expressions of the flyer's clock: Survey writes Map = [t, t+1, t+2, t+3] (t: the flyer engine's seconds),
     * ChooseSector writes Heading = 1000 + Map[0] (rising) and Confidence writes Certainty = 1000 - Map[0] (falling)
     * for every such Map; a value from before the parameters took effect (the file's expressions; -1 from the new
     * ones on an old Map) is told apart by its shape and left out of the order, not out of the count.
     */
    @Test
    void shouldStoreOneRunWithEveryValueOnceInOrderAndNoStandIns() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig())) {
            logger.start();
            long streamsBefore = database.fixture().count("SELECT coalesce(max(run_id), 0) FROM fdnet_run");
            String loggerAddress = "127.0.0.1:" + logger.receiverPort();
            int namingPort = FdnetChildProcess.freePort();
            start("naming", List.of("naming", "--port", Integer.toString(namingPort)), "fdnet naming ready");
            String naming = OrbSettings.namingCorbaloc(OrbSettings.LOOPBACK, namingPort);
            FdnetChildProcess flyer = start("host flyer", List.of("host", "--name", "flyer", "--naming", naming),
                    "fdnet host flyer ready");
            FdnetChildProcess crawler = start("host crawler", List.of("host", "--name", "crawler", "--naming", naming),
                    "fdnet host crawler ready");
            FdnetChildProcess run = start("run two-robots", List.of("run", "../../networks/two-robots.fdn", "--naming",
                    naming, "--as", "operator-station", "--for", "6s", "--logger", loggerAddress,
                    "--param", "Survey:expression=[t, t + 1, t + 2, t + 3]",
                    "--param", "ChooseSector:expression=Map[3] - Map[0] > 2.5 ? 1000 + Map[0] : -1",
                    "--param", "Confidence:expression=Map[3] - Map[0] > 2.5 ? 1000 - Map[0] : -1"),
                    "running on 3 hosts");
            assertThat(run.awaitExit(120_000)).as(String.join("\n", run.output())).isZero();
            String runId = run.output().stream().map(RUN_STARTED::matcher).filter(Matcher::find)
                    .map(m -> m.group(1)).findFirst().orElseThrow();

            String streams = " FROM fdnet_run r JOIN fdnet_network_run n USING (network_run_id) WHERE n.run_uuid = '"
                    + runId + "'";
            // One run: every stream recorded since the test began (one per process) is filed under it.
            assertThat(database.fixture().text("SELECT string_agg(DISTINCT coalesce(n.run_uuid::text, 'none'), ',')"
                    + " FROM fdnet_run r LEFT JOIN fdnet_network_run n USING (network_run_id) WHERE r.run_id > "
                    + streamsBefore)).isEqualTo(runId);
            assertThat(database.fixture().text("SELECT n.network || ' ' || array_to_string(n.hosts, ',')" + streams
                    + " LIMIT 1")).isEqualTo("two-robots flyer,crawler,operator-station");
            assertThat(database.fixture().text("SELECT string_agg(r.host, ',' ORDER BY r.host)" + streams))
                    .isEqualTo("crawler,flyer,operator-station");
            // The coordinator measured each host's clock: one machine, so every offset is far below a second.
            assertThat(database.fixture().count("SELECT max(abs(r.clock_offset))" + streams)).isLessThan(1_000_000);
            // Each host's stream holds exactly what that host says the logger committed of its part (the --param
            // values are written into the definition before the start, so no node is named twice).
            for (String host : List.of("flyer", "crawler", "operator-station")) {
                String stream = database.fixture().text("SELECT r.run_uuid::text" + streams + " AND r.host = '"
                        + host + "'");
                assertThat(rowsOf(stream)).as("rows of host %s", host)
                        .isEqualTo(reportedCount(run, "host " + host + ": "));
            }
            // Each Data is one node of the run, on its home host: the stand-ins (Map on the crawler, Heading and
            // Certainty on the operator's station) are not recorded.
            String nodes = "SELECT string_agg(x.node || '@' || r.host, ',' ORDER BY x.node) FROM fdnet_node x"
                    + " JOIN fdnet_run r USING (run_id) JOIN fdnet_network_run n USING (network_run_id)"
                    + " WHERE x.kind = 'data' AND n.run_uuid = '" + runId + "'";
            assertThat(database.fixture().text(nodes)).isEqualTo("Certainty@crawler,Heading@crawler,Map@flyer");
            // Every Data's values in time order, as its home host wrote them: each once, each after the one before.
            String ofData = "(SELECT x.sourceid FROM fdnet_node x JOIN fdnet_run r USING (run_id) JOIN fdnet_network_run n"
                    + " USING (network_run_id) WHERE n.run_uuid = '" + runId + "' AND x.node = '";
            List<Double> map = mapFirstElements(ofData + "Map')");
            assertStrictlyOrdered("Map[0]", map, 1, ofData + "Map')");
            List<Double> heading = valuesAfterTheParameters(ofData + "Heading')");
            assertStrictlyOrdered("Heading", heading, 1, ofData + "Heading')");
            List<Double> certainty = valuesAfterTheParameters(ofData + "Certainty')");
            assertStrictlyOrdered("Certainty", certainty, -1, ofData + "Certainty')");
            // ... and each crawler value was computed from a Map value the flyer stored: nothing made up or mixed up
            for (double h : heading) {
                assertThat(map).as("the Map behind Heading %s", h).anySatisfy(m -> assertThat(m).isCloseTo(h - 1000,
                        org.assertj.core.data.Offset.offset(1e-9)));
            }
            for (double c : certainty) {
                assertThat(map).as("the Map behind Certainty %s", c).anySatisfy(m -> assertThat(m).isCloseTo(1000 - c,
                        org.assertj.core.data.Offset.offset(1e-9)));
            }
            for (String data : List.of("Map", "Heading", "Certainty")) {
                String of = " FROM datavalue_log WHERE sourceid = " + ofData + data + "')";
                assertThat(database.fixture().count("SELECT count(*)" + of)).as(data).isPositive()
                        .isEqualTo(database.fixture().count("SELECT count(DISTINCT time)" + of));
            }
            flyer.stop(60_000);
            crawler.stop(60_000);
        }
    }

    private static final Pattern RUN_STARTED = Pattern.compile("run ([0-9a-f-]{36}) of two-robots started");

    /**
     * {@code values}, a Data's values in time order, each strictly above ({@code direction} 1) or below (-1) the one
     * before it: no value twice, none out of order; at least ten of them (the run makes about fifty).
     */
    private static void assertStrictlyOrdered(String data, List<Double> values, int direction, String sourceId)
            throws SQLException {
        assertThat(values).as("%s: %s", data, database.fixture().text("SELECT string_agg(value, ' | ' ORDER BY time)"
                + " FROM datavalue_log WHERE sourceid = " + sourceId)).hasSizeGreaterThan(10);
        for (int i = 1; i < values.size(); i++) {
            assertThat(Math.signum(values.get(i) - values.get(i - 1))).as("%s value %d of %d: %s after %s", data, i,
                    values.size(), values.get(i), values.get(i - 1)).isEqualTo((double) direction);
        }
    }

    /** A crawler Data's values in time order, less those from before the --param expressions (-1, or below 500). */
    private static List<Double> valuesAfterTheParameters(String sourceId) throws SQLException {
        List<Double> values = new ArrayList<>();
        for (String text : valuesInTimeOrder(sourceId)) {
            double v = Double.parseDouble(text);
            if (v > 500) { // 1000 ± the flyer's seconds; the file's expressions give 0..270 and 0..1
                values.add(v);
            }
        }
        return values;
    }

    /** Map[0] of every Map value the --param expression wrote ([t, t+1, t+2, t+3]), in time order. */
    private static List<Double> mapFirstElements(String mapSourceId) throws SQLException {
        List<Double> firsts = new ArrayList<>();
        for (String text : valuesInTimeOrder(mapSourceId)) {
            String[] parts = text.split(",");
            double first = Double.parseDouble(parts[0]);
            if (parts.length == 4 && Math.abs(Double.parseDouble(parts[3]) - first - 3.0) < 0.01) { // t is read once per element
                firsts.add(first);
            }
        }
        return firsts;
    }

    /** Every value of node {@code sourceId} as stored, in time order. */
    private static List<String> valuesInTimeOrder(String sourceId) throws SQLException {
        List<String> values = new ArrayList<>();
        try (java.sql.Connection c = database.fixture().target().open();
             java.sql.Statement s = c.createStatement();
             java.sql.ResultSet rs = s.executeQuery("SELECT value FROM datavalue_log WHERE sourceid = " + sourceId
                     + " ORDER BY time")) {
            while (rs.next()) {
                values.add(rs.getString(1));
            }
        }
        return values;
    }

    private FdnetChildProcess start(String label, List<String> args, String readyMarker) {
        FdnetChildProcess p = FdnetChildProcess.start(label, args, readyMarker, 90_000);
        processes.add(p);
        return p;
    }

    /** Waits until the first crawler's Heading values are in the database; returns that crawler's run id. */
    private static String awaitCrawlerValuesCommitted() throws SQLException, InterruptedException {
        long deadline = System.currentTimeMillis() + 90_000;
        String sql = "SELECT count(*) FROM datavalue_log WHERE sourceid IN (SELECT n.sourceid FROM fdnet_node n"
                + " JOIN fdnet_run r USING (run_id) WHERE r.core_name = 'fdnet host crawler' AND n.node = 'Heading')";
        while (database.fixture().count(sql) < 20) {
            assertThat(System.currentTimeMillis()).as("crawler values reach the database").isLessThan(deadline);
            Thread.sleep(200);
        }
        return database.fixture().text("SELECT run_uuid::text FROM fdnet_run WHERE core_name = 'fdnet host crawler'");
    }

    private static void awaitLine(FdnetChildProcess p, Predicate<String> line) throws InterruptedException {
        long deadline = System.currentTimeMillis() + 90_000;
        while (p.output().stream().noneMatch(line)) {
            assertThat(System.currentTimeMillis()).as(String.join("\n", p.output())).isLessThan(deadline);
            Thread.sleep(100);
        }
    }

    private static String committedRun(FdnetChildProcess p, String host) {
        return p.output().stream().filter(l -> l.contains(host + ": logger: all ")).map(COMMITTED::matcher)
                .filter(Matcher::find).map(m -> m.group(2)).findFirst()
                .orElseThrow(() -> new AssertionError(host + " did not report its events committed (exit "
                        + p.awaitExit(0) + "):\n" + String.join("\n", p.output())));
    }

    private static long reportedCount(FdnetChildProcess p) {
        return reportedCount(p, "fdnet host ");
    }

    private static long reportedCount(FdnetChildProcess p, String prefix) {
        return p.output().stream().filter(l -> l.startsWith(prefix) && l.contains(": logger: all "))
                .map(COMMITTED::matcher).filter(Matcher::find).map(m -> Long.parseLong(m.group(1).replace(",", "")))
                .findFirst().orElseThrow();
    }

    private static String ofRun(String runUuid) {
        return " WHERE sourceid IN (SELECT n.sourceid FROM fdnet_node n JOIN fdnet_run r USING (run_id)"
                + " WHERE r.run_uuid = '" + runUuid + "')";
    }

    private static long rowsOf(String runUuid) throws SQLException {
        String where = ofRun(runUuid);
        return database.fixture().count("SELECT count(*) FROM datavalue_log" + where)
                + database.fixture().count("SELECT count(*) FROM procvalue_log" + where)
                + database.fixture().count("SELECT count(*) FROM netcommand_log" + where)
                + database.fixture().count("SELECT count(*) FROM fdnet_node" + where + " AND node IS NOT NULL");
    }

    private static void assertValuesStoredOnceInOrder(String runUuid, String data) throws SQLException {
        String where = " WHERE sourceid = (SELECT n.sourceid FROM fdnet_node n JOIN fdnet_run r USING (run_id)"
                + " WHERE r.run_uuid = '" + runUuid + "' AND n.module = 'main' AND n.node = '" + data + "')";
        long values = database.fixture().count("SELECT count(*) FROM datavalue_log" + where);
        assertThat(values).as("values of %s in run %s", data, runUuid).isGreaterThan(5);
        assertThat(database.fixture().count("SELECT count(DISTINCT time) FROM datavalue_log" + where))
                .as("distinct times of %s in run %s", data, runUuid).isEqualTo(values);
    }
}

package org.fdnet.logger;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fdnet.testing.CliRun;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.RegisterExtension;

/** {@code fdnet run … --logger}: every event the run reports is in PostgreSQL, kind by kind. */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class RunWithLoggerTest {
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    private static long reported(String out, String kind) {
        Matcher m = Pattern.compile(kind + "\\s+([\\d,]+)").matcher(out);
        return m.find() ? Long.parseLong(m.group(1).replace(",", "")) : 0;
    }

    @Test
    void shouldRecordEveryEventOfARunInPostgresql() throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig())) {
            logger.start();
            CliRun cli = new CliRun();
            int exit = cli.fdnet("run", "../../networks/roq-motion.fdn", "--for", "2s", "--set", "Walk/I want to walk=0.5",
                    "--logger", "127.0.0.1:" + logger.receiverPort());
            String out = cli.output();
            assertThat(exit).as(out).isZero();
            Matcher run = Pattern.compile("logger: all ([\\d,]+) events of run ([0-9a-f-]{36}) committed").matcher(out);
            assertThat(run.find()).as(out).isTrue();
            long total = Long.parseLong(run.group(1).replace(",", ""));
            String ofRun = " WHERE sourceid IN (SELECT n.sourceid FROM fdnet_node n JOIN fdnet_run r USING (run_id)"
                    + " WHERE r.run_uuid = '" + run.group(2) + "')";
            long values = database.fixture().count("SELECT count(*) FROM datavalue_log" + ofRun);
            long statuses = database.fixture().count("SELECT count(*) FROM procvalue_log" + ofRun);
            long commands = database.fixture().count("SELECT count(*) FROM netcommand_log" + ofRun);
            long names = database.fixture().count("SELECT count(*) FROM fdnet_node" + ofRun + " AND node IS NOT NULL");
            // The summary is printed while the network still runs; its closing adds a few events (Relations
            // stopping), which the client's own count ("all N events committed") includes.
            assertThat(values).isGreaterThanOrEqualTo(reported(out, "DataValueEvent")).isGreaterThan(100);
            assertThat(statuses).isGreaterThanOrEqualTo(reported(out, "RelationValueEvent"));
            assertThat(commands).isGreaterThanOrEqualTo(reported(out, "NetworkCommandEvent"));
            assertThat(names).isEqualTo(reported(out, "NodeNamedEvent")).isPositive();
            assertThat(values + statuses + commands + names).isEqualTo(total);
        }
    }
}

package org.fdnet.logger.store;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.Statement;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RunIdentity;
import org.fdnet.event.ValueType;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.PostgresPerClass;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import org.junit.jupiter.api.extension.RegisterExtension;

/** Schema 2: one network run over several cores (hosts), and the migration of a schema 1 database. */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class NetworkRunSchemaTest {
    @RegisterExtension
    static final PostgresPerClass database = new PostgresPerClass();

    @TempDir
    Path journals;

    /** The tables as schema 1 made them (before runs had an identity of their own). */
    private static final String[] SCHEMA_1 = {
        "CREATE TABLE datavalue_log (sourceid integer NOT NULL, time bigint NOT NULL, value text,"
                + " typevalue smallint, PRIMARY KEY (sourceid, time))",
        "CREATE TABLE procvalue_log (sourceid integer NOT NULL, time bigint NOT NULL, value text,"
                + " PRIMARY KEY (sourceid, time))",
        "CREATE TABLE netcommand_log (id_db serial PRIMARY KEY, sourceid integer, sourcetype text,"
                + " command text, params_id text, params_type text, time bigint)",
        "CREATE TABLE fdnet_run (run_id serial PRIMARY KEY, run_uuid uuid NOT NULL UNIQUE,"
                + " core_name text NOT NULL, first_seen timestamptz NOT NULL DEFAULT now(),"
                + " committed_seq bigint NOT NULL DEFAULT 0)",
        "CREATE TABLE fdnet_node (sourceid integer PRIMARY KEY,"
                + " run_id integer NOT NULL REFERENCES fdnet_run (run_id), local_id integer NOT NULL,"
                + " kind text, module text, node text, named_at bigint, UNIQUE (run_id, local_id))",
        "CREATE SEQUENCE fdnet_sourceid_block INCREMENT BY 1000 START WITH 1",
        "INSERT INTO fdnet_run (run_uuid, core_name, committed_seq)"
                + " VALUES ('00000000-0000-0000-0000-000000000001', 'fdnet host flyer', 3)",
        "SELECT nextval('fdnet_sourceid_block')", // the logger reserved source ids 1..1000 for that run
        "INSERT INTO fdnet_node VALUES (1, 1, 0, 'data', 'main', 'Map', 10)",
        "INSERT INTO datavalue_log VALUES (1, 11, '0.5', 3), (1, 12, '0.25', 3)",
    };

    @Test
    void shouldKeepEveryRowOfASchemaOneDatabaseWhenItMigrates() throws Exception {
        try (Connection c = database.fixture().target().open(); Statement s = c.createStatement()) {
            for (String sql : SCHEMA_1) {
                s.execute(sql);
            }
            Schema.create(c);
            Schema.create(c); // twice: a restarted logger migrates nothing again
        }
        assertThat(database.fixture().count("SELECT count(*) FROM datavalue_log WHERE sourceid = 1")).isEqualTo(2);
        assertThat(database.fixture().text("SELECT core_name || ' ' || committed_seq || ' '"
                + " || coalesce(host, 'no host') || ' ' || coalesce(network_run_id, 0) FROM fdnet_run"))
                .isEqualTo("fdnet host flyer 3 no host 0");
        assertThat(database.fixture().text("SELECT node FROM fdnet_node WHERE sourceid = 1")).isEqualTo("Map");
        assertThat(database.fixture().count("SELECT count(*) FROM fdnet_network_run")).isZero();
    }

    @Test
    void shouldFileEveryHostOfOneNetworkRunUnderThatRun() throws Exception {
        RunIdentity run = RunIdentity.start("two-robots", "<network name=\"two-robots\"/>",
                List.of("flyer", "crawler", "base"));
        try (NetworkStateLogger logger = new NetworkStateLogger(database.fixture().loggerConfig())) {
            logger.start();
            for (String host : run.hosts()) {
                Path journal = Files.createDirectories(journals.resolve(host));
                LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(),
                        "fdnet host " + host).withJournal(journal, 1 << 20), run, host);
                client.accept(new NodeNamedEvent(1, 1, NodeKind.DATA, new NodeRef("main", host + " value")));
                client.accept(new DataValueEvent(1, 2, ValueType.LONG, "7"));
                assertThat(client.flush(30_000)).isTrue();
                client.close();
            }
        }
        String ofRun = " FROM fdnet_run r JOIN fdnet_network_run n USING (network_run_id) WHERE n.run_uuid = '"
                + run.id() + "'";
        assertThat(database.fixture().count("SELECT count(*)" + ofRun)).isEqualTo(3);
        assertThat(database.fixture().text("SELECT string_agg(r.host, ',' ORDER BY r.host)" + ofRun))
                .isEqualTo("base,crawler,flyer");
        assertThat(database.fixture().text("SELECT n.network || ' ' || n.definition_sha256 || ' '"
                + " || array_to_string(n.hosts, ',')" + ofRun + " LIMIT 1"))
                .isEqualTo("two-robots " + run.sha256() + " flyer,crawler,base");
        assertThat(database.fixture().count("SELECT count(*) FROM datavalue_log d JOIN fdnet_node x USING (sourceid)"
                + " JOIN fdnet_run r USING (run_id) JOIN fdnet_network_run n USING (network_run_id)"
                + " WHERE n.run_uuid = '" + run.id() + "'")).isEqualTo(3);
    }
}

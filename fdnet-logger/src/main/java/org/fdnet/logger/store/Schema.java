package org.fdnet.logger.store;

import java.sql.Connection;
import java.sql.SQLException;
import java.sql.Statement;

/**
 * The logger's tables, created on first start (see {@code docs/reference/logger.md}). The three event tables are
 * the thesis's, column for column; {@code fdnet_run} and {@code fdnet_node} tell runs apart and name the
 * nodes: a core's node ids are only unique within one run, so each (run, core-local id) gets a global
 * {@code sourceid} from blocks of {@code fdnet_sourceid_block}, and the event tables' keys never collide
 * across runs. {@code fdnet_run.committed_seq} is updated in the same transaction as the events, which is
 * what makes delivery exactly-once. {@code fdnet_network_run} is one run of a network, whatever the number of
 * hosts (cores) that record it; {@link #create} also migrates a database made before it (nothing is dropped).
 */
public final class Schema {
    /** Global source ids are reserved this many at a time. */
    public static final int SOURCE_BLOCK = 1000;

    static final String[] DDL = {
        "CREATE TABLE IF NOT EXISTS datavalue_log (sourceid integer NOT NULL, time bigint NOT NULL, value text,"
                + " typevalue smallint, PRIMARY KEY (sourceid, time))",
        "CREATE TABLE IF NOT EXISTS procvalue_log (sourceid integer NOT NULL, time bigint NOT NULL, value text,"
                + " PRIMARY KEY (sourceid, time))",
        "CREATE TABLE IF NOT EXISTS netcommand_log (id_db serial PRIMARY KEY, sourceid integer, sourcetype text,"
                + " command text, params_id text, params_type text, time bigint)",
        "CREATE TABLE IF NOT EXISTS fdnet_run (run_id serial PRIMARY KEY, run_uuid uuid NOT NULL UNIQUE,"
                + " core_name text NOT NULL, first_seen timestamptz NOT NULL DEFAULT now(),"
                + " committed_seq bigint NOT NULL DEFAULT 0)",
        "CREATE TABLE IF NOT EXISTS fdnet_node (sourceid integer PRIMARY KEY,"
                + " run_id integer NOT NULL REFERENCES fdnet_run (run_id), local_id integer NOT NULL,"
                + " kind text, module text, node text, named_at bigint, UNIQUE (run_id, local_id))",
        "CREATE SEQUENCE IF NOT EXISTS fdnet_sourceid_block INCREMENT BY " + SOURCE_BLOCK + " START WITH 1",
        // Schema 2: one network run over several hosts. Each fdnet_run row is one core's stream of
        // events; the streams of one network run (one per host) point at its fdnet_network_run row. Added in
        // place, so a database of schema 1 keeps every row: its streams have no network run (each is a run of
        // its own, named by its core_name) and no host.
        "CREATE TABLE IF NOT EXISTS fdnet_network_run (network_run_id serial PRIMARY KEY,"
                + " run_uuid uuid NOT NULL UNIQUE, network text NOT NULL, definition text NOT NULL,"
                + " definition_sha256 text NOT NULL, started bigint NOT NULL, hosts text[] NOT NULL)",
        "ALTER TABLE fdnet_run ADD COLUMN IF NOT EXISTS network_run_id integer"
                + " REFERENCES fdnet_network_run (network_run_id)",
        "ALTER TABLE fdnet_run ADD COLUMN IF NOT EXISTS host text",
        // µs the host's clock is ahead of the run's coordinator's (measured at deployment): time - clock_offset
        // puts every host's events on the coordinator's time axis
        "ALTER TABLE fdnet_run ADD COLUMN IF NOT EXISTS clock_offset bigint NOT NULL DEFAULT 0",
    };

    private Schema() {
    }

    public static void create(Connection c) throws SQLException {
        boolean auto = c.getAutoCommit();
        c.setAutoCommit(false);
        try (Statement s = c.createStatement()) {
            // Two loggers starting on one database must not race each other's CREATE ... IF NOT EXISTS.
            s.execute("SELECT pg_advisory_xact_lock(4630)");
            for (String ddl : DDL) {
                s.execute(ddl);
            }
            c.commit();
        } catch (SQLException e) {
            c.rollback();
            throw e;
        } finally {
            c.setAutoCommit(auto);
        }
    }
}

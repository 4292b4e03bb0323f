package org.fdnet.logger.export;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import org.fdnet.logger.PostgresPerClass;
import org.fdnet.logger.cli.ExportCommand;
import org.fdnet.logger.store.DatabaseTarget;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.extension.RegisterExtension;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/** {@code fdnet export} on a real database: the file and its summary, and one clear line for each mistake. */
class ExportCommandTest {
    @RegisterExtension
    static final PostgresPerClass PG = new PostgresPerClass();
    private static int run;

    @TempDir
    Path dir;
    private final StringWriter out = new StringWriter();
    private final StringWriter err = new StringWriter();

    @BeforeAll
    static void recordARun() throws Exception {
        try (Connection c = PG.fixture().target().open()) {
            run = SyntheticRun.write(c, 31, 2000, 2);
        }
    }

    @Test
    void shouldWriteTheRunAndSaySoInASummary() throws Exception {
        Path file = dir.resolve("run.mcap");
        assertThat(export(Integer.toString(run), "--to", file.toString())).as(err.toString()).isZero();
        assertThat(out.toString()).contains("export: run " + run + " (synthetic-31, 2 hosts, 16 nodes)")
                .contains("export: wrote " + file + ": 2,000 messages");
        assertThat(Files.size(file)).isPositive();
    }

    @Test
    void shouldRefuseMistakesWithOneLineAndLeaveNoFile() throws Exception {
        Path file = dir.resolve("x.mcap");
        assertThat(export("999999", "--to", file.toString())).isEqualTo(2);
        assertThat(export("latest", "--to", dir.resolve("x.txt").toString())).isEqualTo(2);
        assertThat(export("latest", "--to", file.toString(), "--nodes", "nosuch")).isEqualTo(2);
        assertThat(export("latest", "--to", file.toString(), "--wide")).isEqualTo(2);
        assertThat(err.toString().lines()).containsExactly("fdnet export: run 999999 is not in the database",
                "fdnet export: --to " + dir.resolve("x.txt") + ": name a .mcap or a .csv file",
                "fdnet export: run " + run + " has no node 'nosuch' (name it Module/Node or Node)",
                "fdnet export: --wide is for a .csv file, not " + file);
        assertThat(file).doesNotExist();
    }

    private int export(String... args) {
        DatabaseTarget db = PG.fixture().target();
        String[] all = new String[args.length + 6];
        System.arraycopy(args, 0, all, 0, args.length);
        System.arraycopy(new String[] {"--db", db.url(), "--db-user", db.user(), "--config",
                dir.resolve("no-such-logger.properties").toString()}, 0, all, args.length, 6);
        return new CommandLine(new ExportCommand()).setOut(new PrintWriter(out, true)).setErr(new PrintWriter(err, true))
                .execute(all);
    }
}

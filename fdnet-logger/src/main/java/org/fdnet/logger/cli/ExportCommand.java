package org.fdnet.logger.cli;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerConfigFile;
import org.fdnet.logger.export.ExportSelection;
import org.fdnet.logger.export.ExportSummary;
import org.fdnet.logger.export.LongCsvSink;
import org.fdnet.logger.export.McapRunSink;
import org.fdnet.logger.export.RecordedNode;
import org.fdnet.logger.export.RecordedRun;
import org.fdnet.logger.export.RunExport;
import org.fdnet.logger.export.RunSink;
import org.fdnet.logger.export.StoredRuns;
import org.fdnet.logger.export.WideCsvSink;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.logger.store.EmbeddedDatabase;
import org.fdnet.logger.store.SourceDirectory;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fdnet export RUN --to FILE.mcap|FILE.csv}: a recorded run as a file the robotics world's tools open. */
@Command(name = "export", mixinStandardHelpOptions = true,
        description = {"Write a recorded run as MCAP (Foxglove, PlotJuggler, Python's mcap) or CSV (pandas, PlotJuggler).",
            "MCAP: one channel per node (/MODULE/NODE, JSON with a JSON Schema), time on the run's common clock,"
                    + " structure changes on /fdnet/structure, the .fdn attached, RoQ runs drawn in 3D.",
            "CSV: time_us,host,module,node,value; --wide: one column per scalar Data, aligned on time."})
public final class ExportCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "RUN", description = "the run: its id as fdnet viewer lists it (\"(run 7)\"), or latest")
    String run;

    @Option(names = "--to", required = true, paramLabel = "FILE",
            description = "the file to write: FILE.mcap or FILE.csv")
    Path file;

    @Option(names = "--wide", description = "CSV: one column per scalar Data, one line per instant (default: the long table)")
    boolean wide;

    @Option(names = "--nodes", split = ",", paramLabel = "NODE",
            description = "only these nodes: Module/Node or Node (any module); default every node")
    List<String> nodes;

    @Option(names = "--from", paramLabel = "S",
            description = "from this many seconds after the run's first value; negative: before its last")
    Double from;

    @Option(names = "--until", paramLabel = "S",
            description = "up to this many seconds after the run's first value; negative: before its last")
    Double until;

    @Option(names = "--scene", paramLabel = "KEY=VALUE", description = "an option of a run's 3D scene in MCAP, e.g."
            + " course=crossing (the RoQ course whose fragile cells to draw: the database does not record it)")
    java.util.Map<String, String> scene = new java.util.HashMap<>();

    @Option(names = "--network", paramLabel = "FILE.fdn", description = "MCAP: attach this network definition when the"
            + " database holds none for the run (a core that named no run, e.g. fdnet demo's)")
    Path network;

    @picocli.CommandLine.Mixin
    DatabaseOptions database;

    @Option(names = "--config", paramLabel = "FILE", description = "logger configuration file (default ~/.fdnet/logger.properties)")
    Path configFile;

    @Spec
    CommandSpec spec;

    private enum Format { MCAP, CSV }

    @Override
    public Integer call() throws Exception {
        Format format;
        LoggerConfig config;
        try {
            format = formatOf(file);
            if (wide && format != Format.CSV) {
                throw new IllegalArgumentException("--wide is for a .csv file, not " + file);
            }
            config = LoggerConfigFile.load(configFile != null ? configFile : LoggerConfigFile.defaultPath());
            database.applyTo(config);
            config.validate();
        } catch (IllegalArgumentException | IllegalStateException e) {
            return fail(2, e.getMessage());
        }
        EmbeddedDatabase embedded = null;
        try {
            DatabaseTarget target;
            if (config.embeddedDatabase()) {
                try {
                    embedded = EmbeddedDatabase.start(config.embeddedDirectory(), 0, true);
                } catch (IOException | RuntimeException e) {
                    return fail(1, "cannot open the embedded database in " + config.embeddedDirectory()
                            + " (is a logger using it? stop it first, or pass --db URL of an external server): " + rootMessage(e));
                }
                target = embedded.target();
            } else {
                target = new DatabaseTarget(config.jdbcUrl(), config.databaseUser(), config.databasePassword());
            }
            return export(target, format);
        } finally {
            if (embedded != null) {
                embedded.close();
            }
        }
    }

    private int export(DatabaseTarget target, Format format) throws IOException {
        try (Connection c = target.open()) {
            StoredRuns runs = new StoredRuns(c);
            RecordedRun recorded;
            ExportSelection selection;
            try {
                recorded = runs.load(run);
                selection = selection(recorded, runs);
            } catch (IllegalArgumentException e) {
                return fail(2, e.getMessage());
            }
            recorded = withDefinition(recorded);
            out().printf("export: run %d (%s, %d %s, %,d nodes) → %s%n", recorded.runId(), recorded.network(),
                    recorded.hosts().size(), recorded.hosts().size() == 1 ? "host" : "hosts", recorded.nodes().size(), file);
            Path parent = file.toAbsolutePath().getParent();
            if (parent != null) {
                Files.createDirectories(parent);
            }
            ExportSummary summary;
            try (OutputStream out = Files.newOutputStream(file)) {
                RunSink sink = switch (format) {
                    case MCAP -> new McapRunSink(out, scene);
                    case CSV -> wide ? new WideCsvSink(out, runs.dataTypes(recorded)) : new LongCsvSink(out);
                };
                summary = new RunExport(c, line -> { out().println(line); out().flush(); }, 2000).export(recorded, selection, sink);
            }
            out().printf("export: wrote %s: %,d %s, %,d %s, %,d bytes in %.2f s (%,d rows read, %,.0f rows/s)%n",
                    file, summary.records(), format == Format.MCAP ? "messages" : "lines", summary.channels(),
                    format == Format.MCAP ? "channels" : "value columns", summary.bytes(), summary.seconds(),
                    summary.rows(), summary.rowsPerSecond());
            return 0;
        } catch (SQLException e) {
            return fail(1, "database " + target + ": " + e.getMessage());
        } catch (IllegalArgumentException e) {
            Files.deleteIfExists(file);
            return fail(2, e.getMessage());
        }
    }

    /** The run with the definition to attach: the database's, else {@code --network}'s (said either way). */
    private RecordedRun withDefinition(RecordedRun r) throws IOException {
        if (r.definition() != null) {
            if (network != null) {
                out().println("export: the database holds the run's own definition; attaching it, not " + network);
            }
            return r;
        }
        if (network == null) {
            out().println("export: the database holds no .fdn for this run; --network FILE attaches one");
            return r;
        }
        String text = Files.readString(network, java.nio.charset.StandardCharsets.UTF_8);
        return new RecordedRun(r.runId(), r.network(), r.uuid(), r.startedMicros(), r.hosts(), text,
                org.fdnet.event.RunIdentity.sha256Of(text), r.streams(), r.nodes());
    }

    private ExportSelection selection(RecordedRun recorded, StoredRuns runs) throws SQLException {
        List<Integer> ids = new ArrayList<>();
        if (nodes != null) {
            for (String name : nodes) {
                String wanted = name.trim();
                int before = ids.size();
                for (RecordedNode n : recorded.nodes().values()) {
                    if (SourceDirectory.matches(new org.fdnet.netinfo.NodeRef(n.module(), n.node()), wanted)) {
                        ids.add(n.sourceId());
                    }
                }
                if (ids.size() == before) {
                    throw new IllegalArgumentException("run " + recorded.runId() + " has no node '" + wanted
                            + "' (name it Module/Node or Node)");
                }
            }
        }
        long start = Long.MIN_VALUE;
        long end = Long.MAX_VALUE;
        if (from != null || until != null) {
            long[] span = runs.timeSpan(recorded);
            if (from != null) {
                start = at(span, from);
            }
            if (until != null) {
                end = at(span, until);
            }
        }
        return new ExportSelection(ids, nodes == null, start, end);
    }

    /** Seconds after the run's first value, or (negative) before its last, as µs on the common clock. */
    private static long at(long[] span, double seconds) {
        long offset = Math.round(seconds * 1e6);
        return seconds < 0 ? span[1] + offset : span[0] + offset;
    }

    private static Format formatOf(Path file) {
        String name = file.getFileName().toString().toLowerCase(Locale.ROOT);
        if (name.endsWith(".mcap")) {
            return Format.MCAP;
        }
        if (name.endsWith(".csv")) {
            return Format.CSV;
        }
        throw new IllegalArgumentException("--to " + file + ": name a .mcap or a .csv file");
    }

    private java.io.PrintWriter out() {
        return spec.commandLine().getOut();
    }

    private int fail(int code, String message) {
        spec.commandLine().getErr().println("fdnet export: " + message);
        spec.commandLine().getErr().flush();
        return code;
    }

    private static String rootMessage(Throwable e) {
        Throwable t = e;
        while (t.getCause() != null) {
            t = t.getCause();
        }
        return t.getMessage();
    }
}

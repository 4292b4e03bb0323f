package org.fdnet.run;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.corba.cli.ControlOptions;
import org.fdnet.corba.cli.DistributionOptions;
import org.fdnet.runtime.cli.DurationText;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * Every option of a network's run ({@code fdnet run}, the editor's Run): one set for a run on one host and for a
 * run over many. {@link NetworkRun} applies each, or refuses by name one that does not fit the run.
 */
public final class RunOptions {
    @Option(names = "--for", paramLabel = "DURATION", converter = DurationText.class,
            description = "how long to run (5s, 500ms, 2m); default: until interrupted")
    Duration duration;

    @Option(names = "--set", paramLabel = "MODULE/NODE=VALUE",
            description = "set a Data's value once the network runs (repeatable); a bare node name means main")
    List<String> sets = new ArrayList<>();

    @Option(names = "--param", paramLabel = "MODULE/NODE:NAME=VALUE",
            description = "set a node parameter before the network starts (repeatable; added when the file does not give it)")
    List<String> params = new ArrayList<>();

    @Option(names = "--load", paramLabel = "MODULE", description = "also load this module at start (repeatable)")
    List<String> loads = new ArrayList<>();

    @Option(names = "--allow-path", paramLabel = "DIR",
            description = "another folder node classes may be loaded from (besides the file's folder)")
    List<java.nio.file.Path> allowedRoots = new ArrayList<>();

    @Option(names = "--sim", paramLabel = "COURSE",
            description = "join the network to a simulated plant on this course, in real time (RoQ's simulator, from"
                    + " roq-sim: flat, slope, rubble, fragile or a course file); one host only")
    String simCourse;

    @Option(names = "--workers", paramLabel = "N",
            description = "worker threads of the network's engine (default: one per core); in a distributed run,"
                    + " of every host's engine for this run (default: each host's own, fdnet host --workers N)")
    Integer workers;

    @Option(names = "--trace", description = "print every event as it happens; in a distributed run every host's"
            + " own events, each line naming its host (a host that cannot be read fast enough drops lines and the"
            + " run says how many; --logger keeps every event)")
    boolean trace;

    @Option(names = "--logger", paramLabel = "HOST:PORT",
            description = "also record every event with the network state logger at HOST:PORT (see fdnet logger), as"
                    + " one run however many hosts it spans; while it is slow or away events wait in memory and a"
                    + " bounded disk journal")
    String logger;

    @Option(names = "--logger-viewer", paramLabel = "HOST:PORT",
            description = "the viewer port of that logger (fdnet logger prints it; default port 5556): tools attached"
                    + " to this run (fdnet hi --attach) plot from it without asking; the logger protocol does not tell it")
    String loggerViewer;

    @Mixin
    DistributionOptions distribution = new DistributionOptions();

    @Mixin
    ControlOptions control = new ControlOptions();

    /** Options for a run from code (the editor): run until stopped, everything else as on the command line. */
    public static RunOptions defaults() {
        return new RunOptions();
    }

    public RunOptions logger(String hostPort) {
        this.logger = hostPort;
        return this;
    }

    public RunOptions loggerViewer(String hostPort) {
        this.loggerViewer = hostPort;
        return this;
    }

    public RunOptions naming(String corbaloc) {
        distribution.naming(corbaloc);
        return this;
    }

    public RunOptions sim(String course) {
        this.simCourse = course;
        return this;
    }

    public RunOptions duration(Duration d) {
        this.duration = d;
        return this;
    }
}

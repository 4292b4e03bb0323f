package org.fdnet.runtime.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.client.CommitReport;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.RelationState;
import org.fdnet.runtime.RelationStatus;
import org.fdnet.runtime.RuntimeNetwork;
import org.fdnet.runtime.RuntimeOptions;
import org.fdnet.runtime.RuntimeStartException;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.loading.ClassLoadingPolicy;
import org.fdnet.control.LocalLiveNetwork;
import org.fdnet.corba.cli.ControlOptions;
import org.fdnet.corba.cli.DistributionOptions;
import org.fdnet.corba.control.ControlPublication;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code fdnet run FILE}: runs a network on this machine, prints a status line each second and a summary
 * at the end (values computed per Data, events by kind, Relations and their states, failures with causes).
 * Exit 0 when it ran, 1 for a bad file or a network that cannot start, 2 for a bad {@code --set}/{@code --load}.
 */
@Command(name = "run", mixinStandardHelpOptions = true,
        description = {"Run a network; print progress each second and a summary at the end.",
                "Nodes whose <host> names another host run there (fdnet host --name H); see docs/distribution.md.",
                "While it runs it takes commands on standard input: load, unload, hold, resume MODULE;"
                        + " set [MODULE/]NODE/PARAM=VALUE; send [MODULE/]NODE=VALUE; help.",
                "It publishes its control object for fdnet control NAME and fdnet hi --attach NAME (docs/control.md)."})
public final class RunCommand implements Callable<Integer> {
    @Parameters(paramLabel = "FILE", description = "the .fdn network definition")
    Path file;

    @Option(names = "--for", paramLabel = "DURATION", converter = DurationText.class,
            description = "how long to run (5s, 500ms, 2m); default: until interrupted")
    Duration duration;

    @Option(names = "--set", paramLabel = "MODULE/NODE=VALUE",
            description = "set a Data's value once the network runs (repeatable); a bare node name means main")
    List<String> sets = new ArrayList<>();

    @Option(names = "--param", paramLabel = "MODULE/NODE:NAME=VALUE",
            description = "set a node parameter once the network runs (repeatable)")
    List<String> params = new ArrayList<>();

    @Option(names = "--load", paramLabel = "MODULE", description = "also load this module at start (repeatable)")
    List<String> loads = new ArrayList<>();

    @Option(names = "--allow-path", paramLabel = "DIR",
            description = "another folder node classes may be loaded from (besides the file's folder)")
    List<Path> allowedRoots = new ArrayList<>();

    @Option(names = "--sim", paramLabel = "COURSE",
            description = "join the network to a simulated plant on this course, in real time (RoQ's simulator, from"
                    + " roq-sim: flat, slope, rubble, fragile or a course file)")
    String simCourse;

    @Option(names = "--workers", paramLabel = "N", description = "worker threads (default: one per core)")
    Integer workers;

    @Option(names = "--trace", description = "print every event as it happens")
    boolean trace;

    @Option(names = "--logger", paramLabel = "HOST:PORT",
            description = "also record every event with the network state logger at HOST:PORT (see fdnet logger);"
                    + " while it is slow or away events wait in memory and a bounded disk journal")
    String logger;

    @Option(names = "--logger-viewer", paramLabel = "HOST:PORT",
            description = "the viewer port of that logger (fdnet logger prints it; default port 5556): tools attached"
                    + " to this run (fdnet hi --attach) plot from it without asking; the logger protocol does not tell it")
    String loggerViewer;

    @Mixin
    DistributionOptions distribution;

    @Mixin
    ControlOptions control;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        NetworkInfo definition;
        try {
            definition = NetworkRepository.load(file);
        } catch (NetworkFileException e) {
            e.problems().forEach(p -> err.println(p));
            err.flush();
            return 1;
        }
        try {
            distribution.secure(control.host());
        } catch (IllegalArgumentException | IllegalStateException e) {
            err.println("fdnet run: " + e.getMessage());
            err.flush();
            return 2;
        }
        EventCounter counter = new EventCounter();
        if (loggerViewer != null && !loggerViewer.matches("[^:\\s]+:[0-9]{1,5}")) {
            err.println("--logger-viewer " + loggerViewer + ": expected HOST:PORT, e.g. 127.0.0.1:5556");
            err.flush();
            return 2;
        }
        LoggerClient loggerClient = null;
        if (logger != null) {
            try {
                loggerClient = new LoggerClient(LoggerClientSettings.parseAddress(logger, "fdnet run " + name(definition)));
            } catch (IllegalArgumentException e) {
                err.println("--logger " + logger + ": " + e.getMessage());
                err.flush();
                return 2;
            }
            out.printf("recording events with the logger at %s (run %s)%n", logger, loggerClient.run());
        }
        if (simCourse != null && distribution.appliesTo(definition)) {
            err.println("--sim runs the network on this machine only; it does not combine with a distributed run");
            err.flush();
            closeLogger(out, loggerClient);
            return 2;
        }
        if (distribution.appliesTo(definition)) {
            EventSink events = loggerClient == null ? counter : both(counter, loggerClient);
            try {
                return distribution.run(file, definition, duration, allowedRoots, sets, loads, logger, events, out,
                        err);
            } finally {
                closeLogger(out, loggerClient);
            }
        }
        RuntimeOptions options = RuntimeOptions.defaults().sink(counter)
                .classLoading(ClassLoadingPolicy.forNetworkFile(file, allowedRoots));
        if (workers != null) {
            options.workerThreads(workers);
        }
        if (trace) {
            options.sink(new TracePrinter(out, System.currentTimeMillis() * 1000));
        }
        if (loggerClient != null) {
            options.sink(loggerClient);
        }
        out.printf("starting %s (%s)%n", name(definition), file);
        out.flush();
        long started = System.nanoTime();
        RuntimeNetwork network;
        try {
            network = RuntimeNetwork.start(definition, options);
        } catch (RuntimeStartException e) {
            err.println(file + ": the network cannot start:");
            e.problems().forEach(p -> err.println("  " + p));
            err.flush();
            closeLogger(out, loggerClient);
            return 1;
        }
        SimulatedPlant.Run plant = null;
        if (simCourse != null) {
            try {
                plant = attachPlant(network, out);
            } catch (IllegalArgumentException | IllegalStateException e) {
                err.println("--sim " + simCourse + ": " + e.getMessage());
                err.flush();
                network.close();
                closeLogger(out, loggerClient);
                return 2;
            }
        }
        CountDownLatch stop = new CountDownLatch(1);
        CountDownLatch summarized = new CountDownLatch(1);
        // Ctrl-C: stop the run, and keep the JVM alive until the summary is printed (at most 5 s)
        Thread hook = new Thread(() -> {
            stop.countDown();
            try {
                summarized.await(5, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "fdnet-run-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        ControlPublication published = null;
        try {
            Controller controller = network.controller();
            out.printf("running: modules %s, %d worker threads%n", controller.loadedModules(), network.workerThreads());
            out.flush();
            if (!applyRequests(controller, err)) {
                return 2;
            }
            try {
                published = control.publish(new LocalLiveNetwork(publishedName(definition, file), controller,
                        java.util.Optional.ofNullable(loggerViewer)), out);
            } catch (IllegalArgumentException e) {
                err.println(e.getMessage());
                err.flush();
                return 2;
            }
            new ControlCommands(controller, out).readFrom(System.in);
            long end = duration == null ? Long.MAX_VALUE : started + duration.toNanos();
            while (System.nanoTime() < end) {
                long waitNanos = Math.min(TimeUnit.SECONDS.toNanos(1), end - System.nanoTime());
                if (stop.await(Math.max(1, waitNanos), TimeUnit.NANOSECONDS)) {
                    break;
                }
                status(out, network, counter, started);
                if (plant != null) {
                    out.println("  " + plant.status());
                    out.flush();
                }
            }
            summary(out, definition, network, counter, started);
            if (plant != null) {
                out.println(plant.summary());
                out.flush();
            }
        } finally {
            if (published != null) {
                published.close("the network " + publishedName(definition, file) + " stopped");
            }
            if (plant != null) {
                plant.close();
            }
            network.close();
            closeLogger(out, loggerClient);
            summarized.countDown();
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException shuttingDown) {
                // the JVM is already stopping because of Ctrl-C: the summary below still prints
            }
        }
        return 0;
    }

    /** One sink feeding two (the distributed run takes a single sink). */
    private static EventSink both(EventSink first, EventSink second) {
        return new EventSink() {
            @Override
            public void accept(NetworkEvent event) {
                first.accept(event);
                second.accept(event);
            }

            @Override
            public void flush() {
                first.flush();
                second.flush();
            }
        };
    }

    /** Waits (bounded) until the logger committed every event, then says how it went. */
    /** The one {@link SimulatedPlant} on the class path joined to {@code network}. */
    private SimulatedPlant.Run attachPlant(RuntimeNetwork network, PrintWriter out) {
        SimulatedPlant plant = java.util.ServiceLoader.load(SimulatedPlant.class).findFirst()
                .orElseThrow(() -> new IllegalStateException("no simulated plant on the class path (roq-sim provides"
                        + " RoQ's simulator)"));
        return plant.attach(network, simCourse, out);
    }

    private void closeLogger(PrintWriter out, LoggerClient client) {
        if (client == null) {
            return;
        }
        out.printf("waiting for the logger at %s to commit the run's events ...%n", logger);
        out.flush();
        client.close();
        out.println(CommitReport.of(client));
        out.flush();
    }

    private boolean applyRequests(Controller controller, PrintWriter err) {
        for (String module : loads) {
            ChangeOutcome o = controller.load(module);
            if (!o.executed()) {
                err.println("--load " + module + ": " + o.reason());
                err.flush();
                return false;
            }
        }
        for (String set : sets) {
            try {
                ValueAssignment assignment = ValueAssignment.parse(set);
                controller.setValue(assignment.data(), assignment.value());
            } catch (IllegalArgumentException e) {
                err.println("--set " + set + ": " + e.getMessage());
                err.flush();
                return false;
            }
        }
        for (String p : params) {
            int colon = p.indexOf(':');
            int eq = p.indexOf('=', Math.max(colon, 0));
            if (colon < 0 || eq < 0) {
                err.println("--param " + p + ": expected MODULE/NODE:NAME=VALUE");
                err.flush();
                return false;
            }
            ChangeOutcome o = controller.setParameter(NodeRef.parse(p.substring(0, colon).strip(), ModuleInfo.MAIN),
                    p.substring(colon + 1, eq).strip(), p.substring(eq + 1));
            if (!o.executed()) {
                err.println("--param " + p + ": " + o.reason());
                err.flush();
                return false;
            }
        }
        return true;
    }

    private static void status(PrintWriter out, RuntimeNetwork network, EventCounter counter, long started) {
        long failed = network.controller().relationStates().stream()
                .filter(s -> s.status() == RelationStatus.FAILED).count();
        out.printf(Locale.ROOT, "[%6.1fs] firings %,d  values %,d  events %,d  failed %d%n",
                (System.nanoTime() - started) / 1e9, network.firings(), network.writes(), counter.total(), failed);
        out.flush();
    }

    private static void summary(PrintWriter out, NetworkInfo definition, RuntimeNetwork network, EventCounter counter,
                                long started) {
        Controller c = network.controller();
        double seconds = (System.nanoTime() - started) / 1e9;
        out.printf(Locale.ROOT, "%nsummary of %s after %.1f s: %,d firings, %,d values, %,d events%n", name(definition),
                seconds, network.firings(), network.writes(), counter.total());
        out.println("events by kind:");
        for (Map.Entry<String, Long> e : counter.byKind().entrySet()) {
            out.printf(Locale.ROOT, "  %-20s %,d%n", e.getKey(), e.getValue());
        }
        out.println("Datas (values written, last value):");
        for (ModuleInfo m : definition.modules()) {
            for (NodeInfo n : m.nodes()) {
                if (n.kind() != NodeKind.DATA) {
                    continue;
                }
                NodeRef ref = new NodeRef(m.name(), n.name());
                int id = c.nodeId(ref);
                Value v = c.value(ref);
                out.printf(Locale.ROOT, "  %-45s %,8d  %s%n", ref, id < 0 ? 0 : counter.valuesOf(id),
                        v == null ? "(not running)" : shortText(v));
            }
        }
        out.println("Relations (firings, state):");
        List<RelationState> failed = new ArrayList<>();
        for (RelationState s : c.relationStates()) {
            out.printf(Locale.ROOT, "  %-45s %,8d  %s%n", s.relation(), s.firings(), s.status());
            if (s.status() == RelationStatus.FAILED) {
                failed.add(s);
            }
        }
        if (failed.isEmpty()) {
            out.println("failed Relations: none");
        } else {
            out.println("failed Relations:");
            failed.forEach(s -> out.println("  " + s.relation() + ": " + s.cause()));
        }
        out.flush();
    }

    private static String shortText(Value v) {
        String text = v.text();
        if (v.type() == org.fdnet.event.ValueType.DOUBLE || v.type() == org.fdnet.event.ValueType.DOUBLES) {
            StringBuilder b = new StringBuilder(v.length() > 1 || v.type() == org.fdnet.event.ValueType.DOUBLES ? "[" : "");
            for (int i = 0; i < v.length(); i++) {
                b.append(i == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.4f", v.element(i)));
            }
            text = b.append(v.type() == org.fdnet.event.ValueType.DOUBLES ? "]" : "").toString();
        }
        return text.length() > 80 ? text.substring(0, 77) + "..." : text;
    }

    /** The name a run publishes its control object under: the network's, else the file's without {@code .fdn}. */
    public static String publishedName(NetworkInfo definition, Path file) {
        if (definition.name() != null && !definition.name().isBlank()) {
            return definition.name();
        }
        String base = file.getFileName().toString();
        return base.endsWith(".fdn") ? base.substring(0, base.length() - 4) : base;
    }

    private static String name(NetworkInfo n) {
        return n.name() == null ? "(unnamed)" : n.name();
    }
}

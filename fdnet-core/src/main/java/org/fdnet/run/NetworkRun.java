package org.fdnet.run;

import java.io.InputStream;
import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.ServiceLoader;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.fdnet.control.ControlledLiveNetwork;
import org.fdnet.control.LiveNetwork;
import org.fdnet.corba.DeploymentException;
import org.fdnet.corba.DistributedRun;
import org.fdnet.corba.RuntimeLocalNetwork;
import org.fdnet.corba.TraceCollector;
import org.fdnet.corba.control.ControlPublication;
import org.fdnet.event.EventSink;
import org.fdnet.event.RunIdentity;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.NetworkControl;
import org.fdnet.runtime.NetworkEdits;
import org.fdnet.runtime.RelationStatus;
import org.fdnet.runtime.cli.ControlCommands;
import org.fdnet.runtime.cli.SimulatedPlant;
import org.fdnet.runtime.cli.ParameterAssignment;
import org.fdnet.runtime.cli.ValueAssignment;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.runtime.engine.RuntimeStartException;
import org.fdnet.runtime.loading.ClassLoadingPolicy;

/**
 * One run of a network, start to end, the same on one host and on many: it reads the file, decides the run's
 * identity ({@link RunIdentity}, handed to every host that records it), writes {@code --param} into the definition,
 * starts the network here or over its hosts ({@link RunTarget}), applies {@code --load} and {@code --set} through the
 * run's
 * {@link NetworkControl}, publishes the control object, takes standard-input commands, prints a status line each
 * second and a summary, and stops every host's part, committing the run's events, when its time is up, on Ctrl-C
 * or on {@link #stop()}.
 *
 * <pre>
 *   file + --param ─▶ RunIdentity ─▶ LocalTarget (engine [+ plant] [+ LoggerClient])  ─┐
 *                      └─▶ DistributedTarget (DistributedRun: hosts record) ─┴▶ NetworkControl ◀─ --load/--set,
 *                                                                                stdin commands, control object
 *   each second: status line ─▶ … ─▶ summary ─▶ stop: every host's part ends, the logger commits its events
 * </pre>
 *
 * Exit codes: 0 it ran, 1 bad file or a network that cannot start, 2 a bad or refused option.
 */
public final class NetworkRun {
    private final Path file;
    private final RunOptions options;
    private final PrintWriter out;
    private final PrintWriter err;
    private final InputStream commands;
    private final CountDownLatch stop = new CountDownLatch(1);
    private final CountDownLatch running = new CountDownLatch(1);
    private final CountDownLatch stopped = new CountDownLatch(1);
    private volatile RunIdentity identity;
    private volatile LiveNetwork live;
    private int notStarted = 1; // the exit code when the network did not start: 2 when an option was at fault

    /** {@code commands}: where standard-input commands come from ({@code null}: none, e.g. in the editor). */
    public NetworkRun(Path file, RunOptions options, PrintWriter out, PrintWriter err, InputStream commands) {
        this.file = file;
        this.options = options;
        this.out = out;
        this.err = err;
        this.commands = commands;
    }

    /** Ends the run (as its time running out or Ctrl-C would): {@link #run} prints the summary and stops it. */
    public void stop() {
        stop.countDown();
    }

    /** Waits until the network runs (its options applied) or the run ended; the live network, or {@code null}. */
    public LiveNetwork awaitRunning(long timeout, TimeUnit unit) throws InterruptedException {
        running.await(timeout, unit);
        return live;
    }

    /** The run's identity once it started ({@code null} before). */
    public RunIdentity identity() {
        return identity;
    }

    /** Runs until the duration ends, {@link #stop()} or Ctrl-C; returns the exit code. */
    public int run() throws InterruptedException {
        try {
            return runToEnd();
        } finally {
            running.countDown();
        }
    }

    private int runToEnd() throws InterruptedException {
        NetworkInfo definition;
        try {
            definition = NetworkRepository.load(file);
        } catch (NetworkFileException e) {
            e.problems().forEach(err::println);
            err.flush();
            return 1;
        }
        try {
            options.distribution.secure(options.control.host()); // --tls, and no non-loopback address without it
        } catch (IllegalArgumentException | IllegalStateException e) {
            err.println("fdnet run: " + e.getMessage());
            err.flush();
            return 2;
        }
        String refusal = refusal(definition);
        if (refusal != null) {
            err.println(refusal);
            err.flush();
            return 2;
        }
        if (!applyParameters(definition)) {
            return 2;
        }
        EventCounter counter = new EventCounter();
        RuntimeOptions engine = RuntimeOptions.defaults().sink(counter);
        boolean distributed = options.distribution.appliesTo(definition);
        // in a distributed run every host traces its own events, this one too; here only host and link events
        TracePrinter trace = options.trace ? new TracePrinter(out, System.currentTimeMillis() * 1000,
                distributed ? options.distribution.localHostName() : null) : null;
        long started = System.nanoTime();
        RunTarget target;
        if (distributed) {
            target = startDistributed(definition, engine, trace == null ? counter : EventSink.both(counter, trace),
                    trace);
        } else {
            if (options.workers != null) {
                engine.workerThreads(options.workers);
            }
            if (trace != null) {
                engine.sink(trace);
            }
            target = startLocal(definition, engine);
        }
        if (target == null) {
            return notStarted;
        }
        String name = publishedName(definition, file);
        Thread hook = stopOnCtrlC();
        ControlPublication published = null;
        int exit = 0;
        try {
            if (!applyRequests(target.control())) {
                exit = 2;
                return exit;
            }
            live = target.live(name);
            try {
                published = target.publish(live, out);
            } catch (IllegalArgumentException e) {
                err.println(e.getMessage());
                err.flush();
                exit = 2;
                return exit;
            }
            out.flush();
            running.countDown();
            if (commands != null) {
                new ControlCommands(target.control(), out).readFrom(commands);
            }
            long end = options.duration == null ? Long.MAX_VALUE : started + options.duration.toNanos();
            while (System.nanoTime() < end) {
                long waitNanos = Math.min(TimeUnit.SECONDS.toNanos(1), end - System.nanoTime());
                if (stop.await(Math.max(1, waitNanos), TimeUnit.NANOSECONDS)) {
                    break;
                }
                status(target, counter, started);
            }
            new RunSummary(definition, target.engine(), counter).print(out, started);
            target.summary(out);
            out.flush();
            return exit;
        } finally {
            if (published != null) {
                published.close("the network " + name + " stopped");
            }
            if (live instanceof ControlledLiveNetwork controlled) {
                controlled.networkStopped("the network " + name + " stopped"); // tools attached in this process
            }
            if (options.logger != null) {
                out.printf("waiting for the logger at %s to commit the run's events ...%n", options.logger);
                out.flush();
            }
            for (Map.Entry<String, String> committed : target.stop().entrySet()) {
                out.println("host " + committed.getKey() + ": " + committed.getValue());
            }
            out.flush();
            release(hook);
        }
    }

    /** The option that cannot apply to this run, named with why; {@code null} when every one applies. */
    private String refusal(NetworkInfo definition) {
        if (options.loggerViewer != null && !options.loggerViewer.matches("[^:\\s]+:[0-9]{1,5}")) {
            return "--logger-viewer " + options.loggerViewer + ": expected HOST:PORT, e.g. 127.0.0.1:5556";
        }
        if (options.logger != null) {
            try {
                LoggerClientSettings.parseAddress(options.logger, "fdnet run");
            } catch (IllegalArgumentException e) {
                return "--logger " + options.logger + ": " + e.getMessage();
            }
        }
        if (options.workers != null && (options.workers < 1 || options.workers > RuntimeLocalNetwork.MAX_WORKERS)) {
            return "--workers " + options.workers + ": a network's engine runs 1 to " + RuntimeLocalNetwork.MAX_WORKERS
                    + " worker threads";
        }
        if (!options.distribution.appliesTo(definition)) {
            return null;
        }
        if (options.simCourse != null) {
            return "--sim runs the network on this machine only; it does not combine with a distributed run";
        }
        String placed = options.control.placement();
        if (placed != null) {
            return placed + ": a distributed run registers its control object in its naming service, not at a port"
                    + " (use --no-control to publish none)";
        }
        return null;
    }

    private RunTarget startLocal(NetworkInfo definition, RuntimeOptions engine) {
        String host = "localhost";
        identity = RunIdentity.start(publishedName(definition, file), NetworkRepository.toText(definition),
                List.of(host));
        LoggerClient logger = null;
        if (options.logger != null) {
            logger = new LoggerClient(LoggerClientSettings.parseAddress(options.logger, "fdnet run "
                    + identity.network()), identity, host);
            engine.sink(logger);
            out.printf("recording events with the logger at %s (run %s)%n", options.logger, identity.id());
        }
        engine.classLoading(ClassLoadingPolicy.forNetworkFile(file, options.allowedRoots));
        out.printf("starting %s (%s)%n", identity.network(), file);
        out.flush();
        RuntimeNetwork network;
        try {
            network = RuntimeNetwork.start(definition, engine);
        } catch (RuntimeStartException e) {
            err.println(file + ": the network cannot start:");
            e.problems().forEach(p -> err.println("  " + p));
            err.flush();
            closeLogger(logger);
            return null;
        }
        SimulatedPlant.Run plant = null;
        if (options.simCourse != null) {
            try {
                plant = ServiceLoader.load(SimulatedPlant.class).findFirst()
                        .orElseThrow(() -> new IllegalStateException("no simulated plant on the class path (roq-sim"
                                + " provides RoQ's simulator)"))
                        .attach(network, options.simCourse, out);
            } catch (IllegalArgumentException | IllegalStateException e) {
                err.println("--sim " + options.simCourse + ": " + e.getMessage());
                err.flush();
                network.close();
                closeLogger(logger);
                notStarted = 2;
                return null;
            }
        }
        out.printf("running: modules %s, %d worker threads%n", network.controller().loadedModules(),
                network.workerThreads());
        out.flush();
        return new LocalTarget(host, network, plant, logger, options.control, options.loggerViewer);
    }

    private static void closeLogger(LoggerClient logger) {
        if (logger != null) {
            logger.close();
        }
    }

    private RunTarget startDistributed(NetworkInfo definition, RuntimeOptions engine, EventSink hostAndLinkEvents,
                                       TracePrinter trace) {
        String network = publishedName(definition, file);
        if (options.logger != null) {
            out.printf("every host records its part of the run with the logger at %s%n", options.logger);
        }
        if (trace != null) {
            out.printf("--trace: every host's own events (a stand-in's are its Data's home host's), each line naming"
                    + " its host; a host keeps at most %,d lines this process has not read yet and drops the rest,"
                    + " counted%n", TraceCollector.HOST_CAPACITY);
        }
        try {
            DistributedRun run = DistributedRun.start(new DistributedRun.Request(file, definition,
                    options.allowedRoots, options.distribution.orbSettings(), options.distribution.localHostName(),
                    engine, hostAndLinkEvents, options.logger, options.loggerViewer,
                    options.workers == null ? 0 : options.workers, trace),
                    (text, hosts) -> RunIdentity.start(network, text, hosts), out);
            identity = run.run();
            out.printf("run %s of %s started; this process's host runs %d worker threads%n", identity.id(), network,
                    run.localEngine().runtime().workerThreads());
            out.flush();
            return new DistributedTarget(run, !options.control.off());
        } catch (DeploymentException e) {
            err.println(file + ": " + e.getMessage());
            err.flush();
            return null;
        }
    }

    /** --load, then --set, through the run's control: on one host or on the node's home. */
    private boolean applyRequests(NetworkControl control) {
        for (String module : options.loads) {
            ChangeOutcome o = control.load(module);
            if (!o.executed()) {
                return refused("--load " + module, o.reason());
            }
        }
        for (String set : options.sets) {
            ValueAssignment assignment;
            try {
                assignment = ValueAssignment.parse(set);
            } catch (IllegalArgumentException e) {
                return refused("--set " + set, e.getMessage());
            }
            ChangeOutcome o = control.send(assignment.data(), assignment.value());
            if (!o.executed()) {
                return refused("--set " + set, o.reason());
            }
        }
        return true;
    }

    /**
     * Every {@code --param} into the definition before the network starts, so a parameter its class reads only at
     * start (not declared live) takes the value too.
     */
    private boolean applyParameters(NetworkInfo definition) {
        for (String p : options.params) {
            try {
                ParameterAssignment a = ParameterAssignment.parse(p);
                NetworkEdits.setParameter(a.node(), a.name(), a.value()).applyTo(definition);
            } catch (IllegalArgumentException | EditRefusedException e) {
                return refused("--param " + p, e.getMessage());
            }
        }
        return true;
    }

    private boolean refused(String option, String reason) {
        err.println(option + ": " + reason);
        err.flush();
        return false;
    }

    private void status(RunTarget target, EventCounter counter, long started) {
        RuntimeNetwork network = target.engine();
        long failed = network.controller().relationStates().stream()
                .filter(s -> s.status() == RelationStatus.FAILED).count();
        String more = target.status();
        out.printf(Locale.ROOT, "[%6.1fs] firings %,d  values %,d  events %,d  failed %d%s%n",
                (System.nanoTime() - started) / 1e9, network.firings(), network.writes(), counter.total(), failed,
                more.isEmpty() ? "" : "  " + more);
        out.flush();
    }

    /** Ctrl-C stops the run, and keeps the JVM alive until the run has stopped (at most 5 s). */
    private Thread stopOnCtrlC() {
        Thread hook = new Thread(() -> {
            stop.countDown();
            try {
                stopped.await(5, TimeUnit.SECONDS);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }, "fdnet-run-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        return hook;
    }

    private void release(Thread hook) {
        stopped.countDown();
        try {
            Runtime.getRuntime().removeShutdownHook(hook);
        } catch (IllegalStateException shuttingDown) {
            // Ctrl-C: the JVM is already stopping; the run has stopped and said so
        }
    }

    /** The name a run publishes its control object under: the network's, else the file's without {@code .fdn}. */
    public static String publishedName(NetworkInfo definition, Path file) {
        if (definition.name() != null && !definition.name().isBlank()) {
            return definition.name();
        }
        String base = file.getFileName().toString();
        return base.endsWith(".fdn") ? base.substring(0, base.length() - 4) : base;
    }
}

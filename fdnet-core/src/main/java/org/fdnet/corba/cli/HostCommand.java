package org.fdnet.corba.cli;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import org.fdnet.corba.ClassPolicy;
import org.fdnet.corba.CpuLatencyHold;
import org.fdnet.corba.HostHealth;
import org.fdnet.corba.HostProcess;
import org.fdnet.corba.HostUnreachableException;
import org.fdnet.corba.LinkFaults;
import org.fdnet.corba.LinkSettings;
import org.fdnet.corba.LocalNetworks;
import org.fdnet.corba.RuntimeLocalNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code fdnet host}: one host of distributed networks, registered in the naming service by name. */
@Command(name = "host", mixinStandardHelpOptions = true,
        description = "Run an FDNet host: it registers NAME in the naming service and runs the nodes placed on it.")
public final class HostCommand implements Callable<Integer> {
    @Option(names = "--name", required = true, description = "the host name nodes use in their <host> element")
    String name;

    @Option(names = "--port", description = "port to listen on (default: any free port)", defaultValue = "0")
    int port;

    @Option(names = "--allow-path", description = "a folder whose node classes remote creates may load (repeatable)")
    List<Path> allowedPaths = new ArrayList<>();

    @Option(names = "--workers", paramLabel = "N",
            description = "worker threads of this host's engine (default: one per core); a run deployed here with"
                    + " fdnet run --workers M runs M instead, a run without it this many")
    Integer workers;

    @Option(names = "--logger", paramLabel = "HOST:PORT",
            description = "record this host's events with the network state logger at HOST:PORT (see fdnet logger);"
                    + " without it the host records with the logger fdnet run --logger hands over")
    String logger;

    @Option(names = "--hold-cpu-latency",
            description = "keep every CPU of this machine out of deep idle states while this host runs (a wake-up"
                    + " latency of 0 through /dev/cpu_dma_latency; needs root): values arriving at an idle host are"
                    + " handled within microseconds instead of tens of them, at the price of cores that poll instead"
                    + " of sleeping")
    boolean holdCpuLatency;

    @Option(names = "--link-faults", paramLabel = "FILE", hidden = true,
            description = "soak tests: FILE switches faults in this host's outgoing links on (drop=SHARE,delay=MS)"
                    + " and off (empty or missing) while it runs (see fdnet soak)")
    Path linkFaults;

    @Option(names = "--health-every", paramLabel = "SECONDS", hidden = true,
            description = "soak tests: print one line every SECONDS on what this host holds for peers it cannot reach"
                    + " (link values waiting, logger events in memory and in the journal) and its longest link call")
    Integer healthEvery;

    @Mixin
    NamingOptions naming;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        HostProcess host;
        RuntimeOptions options = RuntimeOptions.defaults();
        try {
            if (workers != null) {
                options.workerThreads(workers);
            }
        } catch (IllegalArgumentException e) {
            spec.commandLine().getErr().println("fdnet host " + name + ": --workers " + workers + ": "
                    + e.getMessage());
            return 2;
        }
        CpuLatencyHold held = null;
        if (holdCpuLatency) {
            try {
                held = CpuLatencyHold.hold();
            } catch (IllegalStateException e) {
                spec.commandLine().getErr().println("fdnet host " + name + ": --hold-cpu-latency: " + e.getMessage());
                return 1;
            }
        }
        RuntimeLocalNetwork engine = LocalNetworks.forHost(name, allowedPaths, options);
        try {
            naming.secure("this host");
            if (linkFaults != null) {
                LinkFaults.install(linkFaults);
            }
            if (logger != null) {
                engine.recordWith(logger);
            }
            // each network run this host served ends with what the logger committed of it (tests count it)
            engine.onRunEnded(report -> {
                System.out.println("fdnet host " + name + ": " + report);
                System.out.flush();
            });
            host = HostProcess.start(name, naming.orbSettings().withPort(port), engine, new ClassPolicy(allowedPaths),
                    LinkSettings.defaults());
        } catch (HostUnreachableException | IllegalArgumentException | IllegalStateException e) {
            engine.close();
            spec.commandLine().getErr().println("fdnet host " + name + ": " + e.getMessage()
                    + (e instanceof HostUnreachableException ? " (is `fdnet naming` running there?)" : ""));
            return 1;
        }
        Runtime.getRuntime().addShutdownHook(new Thread(host::close, "fdnet-host-shutdown"));
        System.out.println("fdnet host " + name + " ready (naming " + naming.corbaloc() + ", "
                + engine.runtime().workerThreads() + " worker threads)");
        System.out.flush();
        if (healthEvery != null && healthEvery > 0) {
            reportHealth(host, engine, healthEvery);
        }
        NamingCommand.awaitStop();
        if (held != null) {
            held.close(); // also what keeps the hold reachable until the host stops
        }
        return 0;
    }

    private void reportHealth(HostProcess host, RuntimeLocalNetwork engine, int everySeconds) {
        ScheduledExecutorService reporter = Executors.newSingleThreadScheduledExecutor(r -> {
                    Thread t = new Thread(r, "fdnet-host-health");
                    t.setDaemon(true);
                    return t;
                });
        reporter.scheduleAtFixedRate(() -> {
            System.out.println(HostHealth.line(name, host.servant(), engine));
            System.out.flush();
        }, everySeconds, everySeconds, TimeUnit.SECONDS);
    }
}

package org.fdnet.corba;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import org.fdnet.event.EventSink;
import org.fdnet.event.RunIdentity;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.ModuleTree;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.Placement;
import org.fdnet.runtime.engine.RuntimeOptions;

/**
 * A network deployed over its hosts: this process becomes a host itself (for the {@code localhost} nodes),
 * deploys every host's share through the naming service — each host recording its part of the run — prints what
 * happens to hosts and links, and removes the network from the hosts when it closes. The run's life around it
 * (options, commands, status, summary) is {@code org.fdnet.run.NetworkRun}'s, as for a run on one host.
 */
public final class DistributedRun implements AutoCloseable {
    /**
     * How often the run pings every host. A host that stops answering — dead, or silent behind a partition — is
     * reported lost within this plus the ORB's call timeout ({@link OrbSettings#callTimeoutMillis()}), and a lost host
     * that answers again is re-wired within the same.
     */
    public static final long HOST_PING_MILLIS = 250;
    /**
     * What a distributed run needs: the network, where hosts register, this process's host name and engine
     * options (event sinks), who else hears host and link events ({@code events}), the logger the hosts record with
     * ({@code null}: none but their own), the logger's viewer address the control object tells attached tools, the
     * worker threads of every host's engine for this run (0: each host's own) and where every host's trace lines go
     * ({@code null}: no trace).
     */
    public record Request(Path file, NetworkInfo definition, List<Path> allowedRoots, OrbSettings orbSettings,
                          String localHostName, RuntimeOptions localOptions, EventSink events, String loggerAddress,
                          String loggerViewerAddress, int workers, TraceOutput trace) {
    }

    private final Request request;
    private final DeploymentPlan plan;
    private final RunIdentity run;
    private final HostProcess local;
    private final NetworkDeployment deployment;
    private final DistributedControl control;
    private final TraceCollector trace;
    private final long started;

    private DistributedRun(Request request, DeploymentPlan plan, RunIdentity run, HostProcess local,
                           NetworkDeployment deployment, TraceCollector trace, long started) {
        this.request = request;
        this.plan = plan;
        this.run = run;
        this.local = local;
        this.deployment = deployment;
        this.trace = trace;
        this.started = started;
        this.control = new DistributedControl(deployment);
        CoordinatorServant.publish(local.orb(), control); // every host's Servants now see the whole network
    }

    /** Whether a node of a module loaded at start names a host other than this machine. */
    public static boolean spansHosts(NetworkInfo definition) {
        Set<String> local = lowerCase(Placement.localNames());
        Set<String> atStart = ModuleTree.atStart(definition);
        for (ModuleInfo m : definition.modules()) {
            if (atStart.contains(m.name())) {
                for (NodeInfo n : m.nodes()) {
                    if (!DeploymentPlan.placeOf(n.host(), "", local).isEmpty()) {
                        return true;
                    }
                }
            }
        }
        return false;
    }

    /**
     * Deploys the network: its run is {@code identity} applied to the hosts it spans (and the {@code .fdn} as
     * deployed: relative class paths made absolute).
     *
     * @throws DeploymentException naming the host that could not be started or set up; nothing is left running
     */
    public static DistributedRun start(Request request, RunIdentityMaker identity, PrintWriter out)
            throws DeploymentException {
        NetworkInfo definition = withAbsolutePaths(request.definition(), request.file());
        List<Path> roots = new ArrayList<>(request.allowedRoots());
        roots.add(request.file().toAbsolutePath().getParent());
        DeploymentPlan plan = DeploymentPlan.of(definition, request.localHostName(), lowerCase(Placement.localNames()),
                Set.of());
        RunIdentity run = identity.make(NetworkRepository.toText(definition), List.copyOf(plan.hosts()));
        OrbSettings settings = request.orbSettings();
        out.printf("distributing %s over hosts %s (naming %s; this process is host %s)%n", run.network(), plan.hosts(),
                settings.namingReference(), request.localHostName());
        out.flush();
        HostProcess local;
        RuntimeLocalNetwork engine = LocalNetworks.forHost(request.localHostName(), roots, request.localOptions());
        try {
            local = HostProcess.start(request.localHostName(), settings, engine, new ClassPolicy(roots),
                    LinkSettings.defaults());
        } catch (RuntimeException e) {
            engine.close();
            throw new DeploymentException("cannot start this process's host " + request.localHostName() + ": "
                    + e.getMessage(), e);
        }
        long started = System.nanoTime();
        NetworkDeployment deployment;
        try {
            deployment = NetworkDeployment.start(plan, HostDirectory.connect(local.orb()),
                    Map.of(request.localHostName(), local.reference()), new PrintingListener(out, started),
                    EventSink.both(request.events(), engine::record), LinkSettings.defaults().window(), 10_000, HOST_PING_MILLIS,
                    new RunRecording(run, request.loggerAddress(), request.workers(),
                            request.trace() == null ? 0 : TraceCollector.HOST_CAPACITY));
        } catch (DeploymentException | HostUnreachableException e) {
            local.close();
            throw new DeploymentException("the network cannot be distributed: " + e.getMessage(), e);
        }
        out.printf("running on %d hosts: %s; %d cross-host links%n", plan.hosts().size(), shares(plan),
                plan.links().size());
        out.printf("worker threads for this run: %s%n", workerThreads(plan, deployment));
        out.flush();
        TraceCollector trace = request.trace() == null ? null : TraceCollector.start(deployment, request.trace());
        return new DistributedRun(request, plan, run, local, deployment, trace, started);
    }

    /** Makes a run's identity once the hosts are known. */
    @FunctionalInterface
    public interface RunIdentityMaker {
        RunIdentity make(String definitionAsDeployed, List<String> hosts);
    }

    public RunIdentity run() {
        return run;
    }

    /** Changes across hosts, in two phases (the run's {@code --load}/{@code --set}/{@code --param} and commands). */
    public DistributedControl control() {
        return control;
    }

    /** The deployment: hosts, links, the plan now. */
    public NetworkDeployment deployment() {
        return deployment;
    }

    /** The ORB of this process's host (a control object registers through it in the naming service). */
    public OrbRuntime orb() {
        return local.orb();
    }

    /** {@code HOST:PORT} of the viewer service of the logger the hosts record with, if given. */
    public java.util.Optional<String> loggerViewerAddress() {
        return java.util.Optional.ofNullable(request.loggerViewerAddress());
    }

    /** The run's status line: hosts lost, links broken, values through this process. */
    public String status() {
        long sent = 0;
        long pending = 0;
        for (OutboundLink l : local.servant().outboundLinks()) {
            sent += l.acknowledged();
            pending += l.pending();
        }
        return String.format(Locale.ROOT, "hosts lost %s  links broken %d/%d  values here: received %,d, sent %,d"
                        + " (%,d waiting)", deployment.lostHosts().isEmpty() ? "none" : deployment.lostHosts(),
                deployment.brokenLinks().size(), deployment.plan().links().size(), local.servant().valuesReceived(),
                sent, pending);
    }

    /** Hosts, links and what went through this process's links. */
    public void summary(PrintWriter out) {
        NetworkDeployment d = deployment;
        out.printf(Locale.ROOT, "hosts and links after %.1f s:%n", (System.nanoTime() - started) / 1e9);
        for (String h : d.plan().hosts()) {
            out.printf("  host %-16s %s%n", h, d.lostHosts().contains(h) ? "LOST" : "running");
        }
        for (DeploymentPlan.Link l : d.plan().links()) {
            out.printf("  %-60s %s%n", l, d.brokenLinks().contains(l) ? "BROKEN" : "ok");
        }
        d.recoveryMillis().forEach((h, ms) -> out.printf("  host %s recovered; last re-wiring took %d ms%n", h, ms));
        for (OutboundLink l : local.servant().outboundLinks()) {
            out.printf("  %s: %,d values acknowledged, %,d lost%n", l.description(), l.acknowledged(), l.lost());
        }
        if (trace != null) {
            out.println("  trace so far: " + trace.tally());
        }
        out.flush();
    }

    /** This process's engine (its share of the network). */
    public RuntimeLocalNetwork localEngine() {
        return (RuntimeLocalNetwork) local.network();
    }

    /**
     * Removes the network from every host, ends every host's recording of the run (each waits, bounded, for the
     * logger's commits) and stops this process's host; returns what the logger committed, by host.
     */
    public Map<String, String> stop() {
        if (trace != null) {
            trace.close(); // the last lines every host kept, then each host's trace ends
        }
        deployment.close();
        local.close();
        return deployment.commitReports();
    }

    @Override
    public void close() {
        stop();
    }

    /** {@code flyer 3, crawler 3, run-7668 2}: what each host said it runs, in the plan's order. */
    private static String workerThreads(DeploymentPlan plan, NetworkDeployment deployment) {
        Map<String, Integer> threads = deployment.workerThreads();
        List<String> parts = new ArrayList<>();
        for (String h : plan.hosts()) {
            Integer n = threads.get(h);
            parts.add(h + " " + (n == null || n == 0 ? "(its own)" : n));
        }
        return String.join(", ", parts);
    }

    private static String shares(DeploymentPlan plan) {
        List<String> parts = new ArrayList<>();
        for (String h : plan.hosts()) {
            parts.add(h + " (" + plan.shareOf(h).nodes().size() + " nodes, " + plan.shareOf(h).standIns().size()
                    + " stand-ins)");
        }
        return String.join(", ", parts);
    }

    /** Relative class paths mean the network file's folder; a remote host needs them absolute. */
    static NetworkInfo withAbsolutePaths(NetworkInfo definition, Path file) {
        NetworkInfo copy = definition.copy();
        Path dir = file.toAbsolutePath().getParent();
        for (ModuleInfo m : copy.modules()) {
            for (NodeInfo n : List.copyOf(m.nodes())) {
                if (!n.path().isEmpty() && !Path.of(n.path()).isAbsolute()) {
                    copy.updateNode(new NodeRef(m.name(), n.name()), new NodeInfo(n.kind(), n.name(), n.host(),
                            dir.resolve(n.path()).normalize().toString(), n.className(), n.parameters()));
                }
            }
        }
        return copy;
    }

    private static Set<String> lowerCase(Set<String> names) {
        Set<String> lower = new HashSet<>();
        names.forEach(n -> lower.add(n.toLowerCase(Locale.ROOT)));
        return lower;
    }

    /** Prints host and link changes as they happen. */
    private static final class PrintingListener implements DeploymentListener {
        private final PrintWriter out;
        private final long started;

        PrintingListener(PrintWriter out, long started) {
            this.out = out;
            this.started = started;
        }

        private void say(String text) {
            synchronized (out) {
                out.printf(Locale.ROOT, "[%6.1fs] %s%n", (System.nanoTime() - started) / 1e9, text);
                out.flush();
            }
        }

        @Override
        public void hostLost(String host, String reason) {
            say("host " + host + " LOST (" + reason + "); the other hosts run on");
        }

        @Override
        public void hostRecovered(String host, long outageMillis, long rewireMillis) {
            say("host " + host + " is back after " + outageMillis + " ms; re-created and re-wired in " + rewireMillis + " ms");
        }

        @Override
        public void linkBroken(DeploymentPlan.Link link, String reason) {
            say("link " + link + " BROKEN: " + reason);
        }

        @Override
        public void linkRestored(DeploymentPlan.Link link) {
            say("link " + link + " restored");
        }
    }
}

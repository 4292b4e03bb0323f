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
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.fdnet.event.EventSink;
import org.fdnet.event.client.CommitReport;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.ModuleTree;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.corba.control.ControlPublication;
import org.fdnet.corba.control.DistributedLiveNetwork;
import org.fdnet.runtime.cli.ControlCommands;
import org.fdnet.runtime.cli.ValueAssignment;
import org.fdnet.runtime.Placement;

/**
 * {@code fdnet run FILE} for a network whose nodes name other hosts: this process becomes a host itself
 * (for the {@code localhost} nodes), deploys every host's share through the naming service, prints what
 * happens to hosts and links, and removes the network from the hosts when it stops.
 */
public final class DistributedRun {
    /** What the command line gives a distributed run. */
    public record Request(Path file, NetworkInfo definition, Duration duration, List<Path> allowedRoots,
                          String namingCorbaloc, String localHostName, List<String> sets, List<String> loads,
                          String loggerAddress) {
    }

    private DistributedRun() {
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

    /** Runs until the duration ends or the process is interrupted; returns the exit code. */
    public static int run(Request request, EventSink events, PrintWriter out, PrintWriter err) throws InterruptedException {
        NetworkInfo definition = withAbsolutePaths(request.definition(), request.file());
        List<Path> roots = new ArrayList<>(request.allowedRoots());
        roots.add(request.file().toAbsolutePath().getParent());
        DeploymentPlan plan;
        try {
            plan = DeploymentPlan.of(definition, request.localHostName(), lowerCase(Placement.localNames()),
                    Set.copyOf(request.loads()));
        } catch (IllegalArgumentException e) {
            err.println("--load: " + e.getMessage());
            err.flush();
            return 2;
        }
        OrbSettings settings = OrbSettings.defaults().withNaming(request.namingCorbaloc());
        out.printf("distributing %s over hosts %s (naming %s; this process is host %s)%n",
                definition.name() == null ? request.file() : definition.name(), plan.hosts(),
                request.namingCorbaloc(), request.localHostName());
        out.flush();
        HostProcess local;
        try {
            local = HostProcess.start(request.localHostName(), settings,
                    LocalNetworks.forHost(request.localHostName(), roots), new ClassPolicy(roots), LinkSettings.defaults());
        } catch (RuntimeException e) {
            err.println(request.file() + ": cannot start this process's host: " + e.getMessage());
            err.flush();
            return 1;
        }
        long started = System.nanoTime();
        NetworkDeployment deployment;
        try {
            deployment = NetworkDeployment.start(plan, HostDirectory.connect(local.orb()),
                    Map.of(request.localHostName(), local.reference()), new PrintingListener(out, started), events,
                    LinkSettings.defaults().window(), 10_000, 250, request.loggerAddress());
        } catch (DeploymentException | HostUnreachableException e) {
            err.println(request.file() + ": the network cannot be distributed: " + e.getMessage());
            err.flush();
            local.close();
            return 1;
        }
        CountDownLatch stop = new CountDownLatch(1);
        Thread hook = new Thread(stop::countDown, "fdnet-run-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        DistributedLiveNetwork live = null;
        ControlPublication published = null;
        try {
            out.printf("running on %d hosts: %s; %d cross-host links%n", plan.hosts().size(), shares(plan),
                    plan.links().size());
            out.flush();
            if (!applySets(request.sets(), plan, deployment, err)) {
                return 2;
            }
            DistributedControl control = new DistributedControl(deployment);
            CoordinatorServant.publish(local.orb(), control); // every host's Servants now see the whole network
            live = new DistributedLiveNetwork(publishedName(request), control, deployment);
            published = publishControl(live, local, out, err);
            new ControlCommands(live, out).readFrom(System.in);
            long end = request.duration() == null ? Long.MAX_VALUE : started + request.duration().toNanos();
            while (System.nanoTime() < end) {
                long wait = Math.min(TimeUnit.SECONDS.toNanos(1), end - System.nanoTime());
                if (stop.await(Math.max(1, wait), TimeUnit.NANOSECONDS)) {
                    break;
                }
                status(out, deployment, local, started);
            }
        } finally {
            if (published != null) {
                published.close("the network " + publishedName(request) + " stopped");
            }
            summary(out, deployment, local, started);
            deployment.close();
            local.close();
            if (local.network() instanceof RuntimeLocalNetwork engine) {
                engine.logger().ifPresent(c -> out.println("host " + request.localHostName() + ": "
                        + CommitReport.of(c)));
                out.flush();
            }
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException shuttingDown) {
                // Ctrl-C: the JVM is already stopping; the summary has been printed
            }
        }
        return 0;
    }

    private static String publishedName(Request request) {
        return org.fdnet.runtime.cli.RunCommand.publishedName(request.definition(), request.file());
    }

    /** Registers the run's control object in its naming service; a run that cannot still runs, and says so. */
    private static ControlPublication publishControl(DistributedLiveNetwork live, HostProcess local, PrintWriter out,
                                                     PrintWriter err) {
        try {
            ControlPublication p = ControlPublication.inNaming(live, local.orb());
            out.println(p.announcement());
            out.flush();
            return p;
        } catch (RuntimeException e) {
            err.println("the control object is not published: " + e.getMessage());
            err.flush();
            return null;
        }
    }

    private static boolean applySets(List<String> sets, DeploymentPlan plan, NetworkDeployment deployment,
                                     PrintWriter err) {
        for (String set : sets) {
            ValueAssignment assignment;
            try {
                assignment = ValueAssignment.parse(set);
            } catch (IllegalArgumentException e) {
                err.println("--set " + set + ": " + e.getMessage());
                err.flush();
                return false;
            }
            NodeRef ref = assignment.data();
            String host = plan.hosts().stream()
                    .filter(h -> plan.shareOf(h).nodes().stream().anyMatch(p -> p.ref().equals(ref)))
                    .findFirst().orElse(null);
            if (host == null) {
                err.println("--set " + set + ": no running Data " + ref);
                err.flush();
                return false;
            }
            try {
                deployment.host(host).write(IdlMapping.id(ref), ValueCodec.encode(assignment.value()));
            } catch (org.omg.CORBA.UserException | org.omg.CORBA.SystemException e) {
                err.println("--set " + set + ": host " + host + " refused: "
                        + (e instanceof org.fdnet.corba.idl.Refused r ? r.reason : e.toString()));
                err.flush();
                return false;
            }
        }
        return true;
    }

    private static String shares(DeploymentPlan plan) {
        List<String> parts = new ArrayList<>();
        for (String h : plan.hosts()) {
            parts.add(h + " (" + plan.shareOf(h).nodes().size() + " nodes, " + plan.shareOf(h).standIns().size()
                    + " stand-ins)");
        }
        return String.join(", ", parts);
    }

    private static void status(PrintWriter out, NetworkDeployment d, HostProcess local, long started) {
        long sent = 0;
        long pending = 0;
        for (OutboundLink l : local.servant().outboundLinks()) {
            sent += l.acknowledged();
            pending += l.pending();
        }
        out.printf(Locale.ROOT,
                "[%6.1fs] hosts lost %s  links broken %d/%d  values here: received %,d, sent %,d (%,d waiting)%n",
                (System.nanoTime() - started) / 1e9, d.lostHosts().isEmpty() ? "none" : d.lostHosts(),
                d.brokenLinks().size(), d.plan().links().size(), local.servant().valuesReceived(), sent, pending);
        out.flush();
    }

    private static void summary(PrintWriter out, NetworkDeployment d, HostProcess local, long started) {
        out.printf(Locale.ROOT, "%nsummary after %.1f s:%n", (System.nanoTime() - started) / 1e9);
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
        out.flush();
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

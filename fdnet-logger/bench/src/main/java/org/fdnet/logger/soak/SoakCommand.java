package org.fdnet.logger.soak;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.SQLException;
import java.time.Duration;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;
import org.fdnet.apart.ApartRig;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.cli.DurationText;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code fdnet soak}: two-robots across two hosts with the logger on PostgreSQL, under a schedule of faults, then
 * counted node by node. Exit 0 when every acknowledged value is stored (exactly as often as hosts hold its Data, but
 * for what a host's kill -9 may cost), every fault healed and every kind was injected; 1 otherwise.
 */
@Command(name = "soak", mixinStandardHelpOptions = true,
        description = {"Run two-robots on two hosts with the logger while faults are injected: link faults (calls dropped"
                + " and delayed), kill -9 of a host and of the logger (both started again), PostgreSQL stopped for"
                + " 10 s, the naming service restarted. Then count, per node, values applied against stored,"
                + " duplicates and gaps, and the time each fault took to heal.",
                "With --apart every process runs on a host of its own (a network namespace with its own address; root"
                        + " only) and network faults come in cycles of their own: a host's link black-holed for 5 s, 30 s"
                        + " and 120 s, the logger's and the naming service's black-holed, 5 %% loss on every link, a link"
                        + " throttled to 1 Mbit/s; each is checked against the time bounds of detection, re-wiring, the"
                        + " longest call and a Relation's stall.",
                "Exit 0 when no acknowledged value was lost, 1 otherwise."})
public final class SoakCommand implements Callable<Integer> {
    private static final long VALUE_PERIOD_MILLIS = 50;
    /** Every value is recorded by its Data's home host only (stand-ins do not record values): once. */
    private static final int COPIES = 1;
    private static final long SETTLE_MILLIS = 60_000;
    private static final List<String> HOSTS = List.of("flyer", "crawler");
    /** What the names of the soak's namespaces start with ({@code ip netns list}). */
    private static final String RIG_PREFIX = "fdnetsoak";
    private static final NodeRef SEQ = new NodeRef("main", "Seq");
    private static final NodeRef ECHO = new NodeRef("main", "Echo");
    private static final List<NodeRef> UNCOUNTED = List.of(new NodeRef("main", "Map"), new NodeRef("main", "Heading"),
            new NodeRef("main", "Certainty"));

    @Option(names = "--for", paramLabel = "DURATION", converter = DurationText.class, defaultValue = "60s",
            description = "how long faults are injected (default ${DEFAULT-VALUE}; at least 45s: one cycle of every"
                    + " fault a minute)")
    Duration duration;

    @Option(names = "--network", paramLabel = "FILE",
            description = "the two-robots example to extend (default: networks/two-robots.fdn of this FDNet)")
    Path twoRobots;

    @Option(names = "--work", paramLabel = "DIR",
            description = "folder for the database, the network and the switch files (default: a new temporary one)")
    Path work;

    @Option(names = "--apart", description = "run every process on a host of its own (network namespaces made for the"
            + " soak; needs root) and add the network faults: black holes, loss, a throttled link")
    boolean apart;

    @Option(names = "--cycles", split = ",", paramLabel = "CYCLE",
            description = "with --apart: the cycles to repeat, in order, from network (60 s: every network fault kind,"
                    + " short), plain (60 s: the process faults), partition30 (60 s: a host black-holed 30 s), loss"
                    + " (75 s: 5 %% loss on every link for 60 s), partition120 (180 s: a host black-holed 120 s)"
                    + " (default: network,plain,partition30,plain,loss,plain,partition120,plain)")
    List<String> cycles;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        FaultPlan plan;
        Path network;
        boolean temporary = work == null;
        try {
            if (cycles != null && !apart) {
                throw new IllegalArgumentException("--cycles needs --apart");
            }
            plan = apart ? FaultPlan.apart(duration, cycles != null ? cycles : FaultPlan.APART_ORDER)
                    : FaultPlan.of(duration);
            work = work != null ? Files.createDirectories(work) : Files.createTempDirectory("fdnet-soak-");
            network = SoakNetwork.write(twoRobots != null ? twoRobots : defaultTwoRobots(), work);
        } catch (IllegalArgumentException | IOException e) {
            err.println("fdnet soak: " + e.getMessage());
            return 2;
        }
        Path linkSwitch = work.resolve("link-faults");
        ApartRig rig = null;
        if (apart) {
            try {
                rig = ApartRig.create(RIG_PREFIX, SoakPlacement.PROCESSES);
            } catch (IllegalStateException e) {
                err.println("fdnet soak --apart: " + e.getMessage());
                if (temporary) {
                    deleteTree(work);
                }
                return 1;
            }
        }
        try {
            return soak(out, err, plan, network, linkSwitch, rig, temporary);
        } finally {
            if (rig != null) {
                rig.close();
            }
        }
    }

    private int soak(PrintWriter out, PrintWriter err, FaultPlan plan, Path network, Path linkSwitch, ApartRig rig,
                     boolean temporary) throws Exception {
        SoakPlacement placement = rig == null ? SoakPlacement.loopback() : SoakPlacement.apart(rig);
        out.printf("fdnet soak: %d s of faults on %s (hosts %s, operator, logger on PostgreSQL%s); work folder %s%n",
                duration.toSeconds(), network.getFileName(), HOSTS, rig == null ? ""
                        : "; apart: " + SoakPlacement.PROCESSES.stream().map(p -> p + " " + placement.address(p))
                        .collect(java.util.stream.Collectors.joining(", ")), work);
        out.flush();
        int result;
        try (SoakCluster cluster = new SoakCluster(work, placement)) {
            long fromMicros = System.currentTimeMillis() * 1_000;
            FdnetChildProcess run;
            try {
                cluster.start(HOSTS, linkSwitch.toString());
                run = cluster.startRun(network, duration.toSeconds() + 600, HOSTS.size() + 1);
            } catch (IllegalStateException | IOException e) {
                err.println("fdnet soak: cannot start the soak's processes: " + e.getMessage());
                return 1;
            }
            SoakDatabase database = new SoakDatabase(cluster.databaseTarget(), fromMicros);
            SequenceWriter writer = new SequenceWriter(run, VALUE_PERIOD_MILLIS);
            DeliveryWatch watch = new DeliveryWatch(database, ECHO, SEQ);
            OutputWatch output = new OutputWatch(cluster);
            Thread writing = daemon(writer, "fdnet-soak-writer");
            Thread watching = daemon(watch, "fdnet-soak-watch");
            daemon(output, "fdnet-soak-output");
            long t0 = System.currentTimeMillis();
            out.printf("all processes ready; writing %s every %d ms%n", SequenceWriter.NODE, VALUE_PERIOD_MILLIS);
            out.flush();
            List<InjectedFault> injected = new ArrayList<>();
            for (FaultPlan.Planned f : plan.faults()) {
                sleepUntil(t0 + f.atMillis());
                InjectedFault done = new FaultInjector(cluster, linkSwitch, HOSTS, rig).inject(f);
                injected.add(done);
                out.printf("[%6.1fs] %-16s %-14s over after %,6d ms%n", (done.atMillis() - t0) / 1e3, f.kind(), f.target(),
                        done.overMillis() - done.atMillis());
                out.flush();
            }
            sleepUntil(t0 + duration.toMillis());
            writer.stop();
            writing.join(30_000);
            List<SequenceWriter.Acknowledged> acked = writer.acknowledged();
            long last = acked.isEmpty() ? -1 : acked.get(acked.size() - 1).value();
            long settleDeadline = System.currentTimeMillis() + SETTLE_MILLIS;
            while (last > 0 && watch.firstStored(last, 0) < 0 && System.currentTimeMillis() < settleDeadline) {
                Thread.sleep(250);
            }
            watch.stop();
            watching.join(10_000);
            output.stop();
            List<InjectedFault> healed = new ArrayList<>();
            for (InjectedFault f : injected) {
                // a network fault lasts: its heal counts from the lift (links are in order, so the value sent first
                // after it is stored end to end behind everything that waited through the fault)
                long from = f.kind().network ? f.overMillis() : f.atMillis();
                long value = writer.firstAcknowledgedFrom(from);
                long storedAt = value < 0 ? -1 : watch.firstStored(value, from);
                healed.add(f.healed(storedAt < 0 ? -1 : storedAt - from));
            }
            result = report(out, t0, healed, acked, writer, watch, database, plan,
                    new NetworkFaultCheck(output, database));
        }
        if (result == 0 && temporary) {
            deleteTree(work); // a passed soak's database is of no further use; a failed one's is kept to look into
        }
        return result;
    }

    private static void deleteTree(Path root) throws IOException {
        try (var paths = Files.walk(root)) {
            for (Path p : (Iterable<Path>) paths.sorted(java.util.Comparator.reverseOrder())::iterator) {
                Files.delete(p);
            }
        }
    }

    private int report(PrintWriter out, long t0, List<InjectedFault> faults, List<SequenceWriter.Acknowledged> acked,
                       SequenceWriter writer, DeliveryWatch watch, SoakDatabase database, FaultPlan plan,
                       NetworkFaultCheck check) throws SQLException {
        out.println();
        out.println("faults (healed: from the injection — for a network fault, from its lift — until a value acknowledged"
                + " after it was stored end to end: Seq applied on the flyer, across the link to the crawler's Relay, its"
                + " Echo stored by the crawler):");
        Set<FaultKind> kinds = EnumSet.noneOf(FaultKind.class);
        boolean allHealed = true;
        for (InjectedFault f : faults) {
            kinds.add(f.kind());
            allHealed &= f.healedMillis() >= 0;
            out.printf("  [%6.1fs] %-16s %-14s outage %,7d ms   healed %s%n", (f.atMillis() - t0) / 1e3, f.kind(),
                    f.target(), f.overMillis() - f.atMillis(),
                    f.healedMillis() < 0 ? "NEVER" : String.format("in %,7d ms", f.healedMillis()));
        }
        boolean boundsHeld = NetworkFaultReport.print(out, t0, faults, check);
        List<SequenceCount> counts = List.of(
                SequenceCount.of(SEQ.toString(), database.copiesByValue(SEQ), acked, faults, COPIES, true),
                SequenceCount.of(ECHO.toString(), database.copiesByValue(ECHO), acked, faults, COPIES, false));
        out.println();
        out.printf("per node (rows the database holds for the node's name since the soak began; every value must be"
                + " stored once, by its Data's home host):%n");
        out.printf("  %-14s %8s %8s %8s %6s %6s %10s %14s %11s%n", "node", "applied", "stored", "rows", "lost", "gaps",
                "duplicates", "at host kills", "unexplained");
        long unexplained = 0;
        for (SequenceCount c : counts) {
            unexplained += c.unexplained();
            out.printf("  %-14s %8s %8d %8d %6d %6d %10d %14d %11d%n", c.node(), c.applied() < 0 ? "-" : c.applied(),
                    c.stored(), c.rows(), c.lost(), c.gaps(), c.duplicates(), c.explained(), c.unexplained());
        }
        for (NodeRef n : UNCOUNTED) {
            out.printf("  %-14s %8s %8s %8d   (not a sequence: rows only)%n", n, "-", "-", database.rows(n));
        }
        out.printf("values written %d: acknowledged %d, refused %d (their host was down), unanswered %d%n",
                acked.size() + writer.refused() + writer.unanswered(), acked.size(), writer.refused(), writer.unanswered());
        out.printf("committed Seq rows that later vanished: %d%n", watch.rowsLost());
        Set<FaultKind> missing = EnumSet.noneOf(FaultKind.class);
        plan.faults().forEach(p -> missing.add(p.kind()));
        missing.removeAll(kinds);
        boolean pass = unexplained == 0 && watch.rowsLost() == 0 && allHealed && missing.isEmpty() && !acked.isEmpty()
                && boundsHeld;
        out.println(pass ? "PASSED: no acknowledged value lost or stored twice outside a host's kill -9; every fault healed"
                : "FAILED:" + (unexplained > 0 ? " " + unexplained + " unexplained anomalies;" : "")
                + (watch.rowsLost() > 0 ? " committed rows vanished;" : "") + (allHealed ? "" : " a fault never healed;")
                + (missing.isEmpty() ? "" : " not injected: " + missing + ";") + (acked.isEmpty() ? " nothing acknowledged;" : "")
                + (boundsHeld ? "" : " a network fault's bound was exceeded;"));
        out.flush();
        return pass ? 0 : 1;
    }

    private static Path defaultTwoRobots() {
        String home = System.getProperty("fdnet.home");
        return home != null ? Path.of(home, "networks", "two-robots.fdn") : Path.of("networks", "two-robots.fdn");
    }

    private static Thread daemon(Runnable r, String name) {
        Thread t = new Thread(r, name);
        t.setDaemon(true);
        t.start();
        return t;
    }

    static void sleepUntil(long epochMillis) throws InterruptedException {
        long left = epochMillis - System.currentTimeMillis();
        if (left > 0) {
            Thread.sleep(left);
        }
    }

    static void writeSwitch(Path file, String text) throws IOException {
        Path part = file.resolveSibling(file.getFileName() + ".part");
        Files.writeString(part, text, StandardCharsets.UTF_8);
        Files.move(part, file, java.nio.file.StandardCopyOption.REPLACE_EXISTING, java.nio.file.StandardCopyOption.ATOMIC_MOVE);
    }
}

package org.fdnet.corba.bench;

import java.util.List;
import org.fdnet.corba.ClassPolicy;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.corba.HostDirectory;
import org.fdnet.corba.HostProcess;
import org.fdnet.corba.IdlMapping;
import org.fdnet.corba.LinkSettings;
import org.fdnet.corba.LocalNetwork;
import org.fdnet.corba.LocalNetworks;
import org.fdnet.corba.NamingService;
import org.fdnet.corba.OrbSettings;
import org.fdnet.corba.idl.ConnectionSpec;
import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.NodeSpec;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * The hosts of {@code fdnet bench corba}, wired with the same Host operations {@code fdnet run} uses. Each
 * host runs the single-host engine; bench-b is a separate JVM.
 *
 * <pre>
 *   bench-a (this JVM)          bench-b (child JVM)                               bench-a / bench-probe (this JVM)
 *   Data ping  ──link 1──▶ stand-in ping ─Reader─▶ Relation stamp ─Writer─▶ Data hop ──link 2──▶ bench-a: Data hop
 *                                                                                              (observer)
 *   Data seq   ──link 3──▶ stand-in seq  ─────────────────────────────────────────────link 4──▶ bench-probe: Data seq
 *                                                                                              (observer)
 * </pre>
 *
 * The round trip: a value written into bench-a's {@code ping} (its {@code nanoTime}) reaches the Relation
 * {@code stamp} on bench-b, which writes the one-way time into bench-b's Data {@code hop}; that comes back
 * to bench-a's Data {@code hop} (two hops, two host boundaries, timed on one clock) — the loop of a sensor
 * and actuator on one host around a controller on another. The rate: every value of {@code seq} crosses to
 * bench-b's Data and on to bench-probe, a host with its own ORB in bench-a's JVM, where each arrival is
 * counted (a relayed value never goes back to the host it came from, so it cannot end on bench-a).
 */
final class BenchTopology implements AutoCloseable {
    private static final String M = "bench";
    private static final NodeRef PING = new NodeRef(M, "ping");
    private static final NodeRef STAMP = new NodeRef(M, "stamp");
    private static final NodeRef HOP = new NodeRef(M, "hop");
    private static final NodeRef SEQ = new NodeRef(M, "seq");

    private final FdnetChildProcess child;
    private final HostProcess a;
    private final HostProcess probe;
    private final Host b;

    private BenchTopology(FdnetChildProcess child, HostProcess a, HostProcess probe, Host b) {
        this.child = child;
        this.a = a;
        this.probe = probe;
        this.b = b;
    }

    static BenchTopology start(LinkSettings links) {
        return start(links, List.of());
    }

    /** As above, {@code fdnet host bench-b} started with {@code childArgs} too (e.g. {@code --tls FILE}). */
    static BenchTopology start(LinkSettings links, List<String> childArgs) {
        int namingPort = FdnetChildProcess.freePort();
        String corbaloc = NamingService.start(OrbSettings.defaults().withPort(namingPort), 15_000);
        List<String> args = new java.util.ArrayList<>(List.of("host", "--name", "bench-b", "--naming", corbaloc));
        args.addAll(childArgs);
        FdnetChildProcess child = FdnetChildProcess.start("host bench-b", args, " ready", 60_000);
        HostProcess a = null;
        HostProcess probe = null;
        try {
            OrbSettings settings = OrbSettings.defaults().withNaming(corbaloc);
            a = HostProcess.start("bench-a", settings, LocalNetworks.forHost("bench-a", List.of()),
                    new ClassPolicy(List.of()), links);
            probe = HostProcess.start("bench-probe", settings, LocalNetworks.forHost("bench-probe", List.of()),
                    new ClassPolicy(List.of()), links);
            Host b = HostDirectory.connect(a.orb()).find("bench-b")
                    .orElseThrow(() -> new IllegalStateException("bench-b did not register"));
            wire(a.reference(), b, probe.reference(), links.window());
            return new BenchTopology(child, a, probe, b);
        } catch (RuntimeException | org.omg.CORBA.UserException e) {
            if (probe != null) {
                probe.close();
            }
            if (a != null) {
                a.close();
            }
            child.close();
            throw new IllegalStateException("cannot set up the benchmark: " + describe(e), e);
        }
    }

    private static String describe(Exception e) {
        return e instanceof org.fdnet.corba.idl.Refused r ? "refused: " + r.reason : e.toString();
    }

    private static void wire(Host a, Host b, Host probe, int window) throws org.omg.CORBA.UserException {
        a.createNode(IdlMapping.spec(M, longData(PING)));
        a.createNode(IdlMapping.spec(M, longData(SEQ)));
        b.createStandIn(IdlMapping.spec(M, longData(PING)), "bench-a");
        b.createStandIn(IdlMapping.spec(M, longData(SEQ)), "bench-a");
        // seq needs a reader on bench-b for its stand-in to exist: the hop's Relation reads it too and
        // ignores it (it measures input 0 only).
        b.loadModule(M, new NodeSpec[] {
            IdlMapping.spec(M, new NodeInfo(NodeKind.RELATION, STAMP.node(), "", "", HopStamp.class.getName(), List.of())),
            IdlMapping.spec(M, longData(HOP))}, new ConnectionSpec[] {
                IdlMapping.spec(ConnectionInfo.reader(PING, STAMP)),
                IdlMapping.spec(ConnectionInfo.writer(STAMP, HOP)),
                IdlMapping.spec(ConnectionInfo.reader(SEQ, STAMP))});
        a.createNode(IdlMapping.spec(M, longData(HOP)));
        probe.createNode(IdlMapping.spec(M, longData(SEQ)));
        link(1, PING, a, "bench-a", b, "bench-b", window);
        link(2, HOP, b, "bench-b", a, "bench-a", window);
        link(3, SEQ, a, "bench-a", b, "bench-b", window);
        link(4, SEQ, b, "bench-b", probe, "bench-probe", window);
    }

    private static void link(long id, NodeRef data, Host from, String fromName, Host to, String toName, int window)
            throws org.omg.CORBA.UserException {
        to.acceptLink(id, IdlMapping.id(data), fromName);
        from.forward(id, IdlMapping.id(data), to, toName, window);
    }

    private static NodeInfo longData(NodeRef ref) {
        return new NodeInfo(NodeKind.DATA, ref.node(), "", "", "LongData", List.of());
    }

    Host remoteHost() {
        return b;
    }

    /** Writes the hop probe (its value: now, in nanoTime) on bench-a, as a sensor there would. */
    void writePing(long nanoTime) {
        a.network().write(PING, nanoTime);
    }

    /** Writes one value of the rate stream on bench-a. */
    void writeSeq(long value) {
        a.network().write(SEQ, value);
    }

    /** Sees each one-way hop time (ns) as bench-b's Data {@code hop} comes back to bench-a. */
    AutoCloseable observeHops(LocalNetwork.ValueObserver observer) {
        return a.network().observe(HOP, observer);
    }

    AutoCloseable observeSeq(LocalNetwork.ValueObserver observer) {
        return probe.network().observe(SEQ, observer);
    }

    String describe() {
        return "bench-a:ping -> bench-b:stamp -> bench-b:hop -> bench-a:hop; bench-a:seq -> bench-b:seq -> bench-probe";
    }

    /** The process id of bench-b's JVM (for its CPU time). */
    long remotePid() {
        return child.pid();
    }

    String[] linkReport() {
        return a.servant().outboundLinks().stream()
                .map(l -> l.description() + ": " + l.acknowledged() + " acknowledged, " + l.lost() + " lost, "
                        + l.aheadSends() + " values sent ahead from the writer's thread")
                .toArray(String[]::new);
    }

    @Override
    public void close() {
        probe.close();
        a.close();
        child.close();
    }
}

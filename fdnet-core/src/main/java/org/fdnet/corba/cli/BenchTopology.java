package org.fdnet.corba.cli;

import java.util.List;
import org.fdnet.corba.ClassPolicy;
import org.fdnet.corba.DataOnlyNetwork;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.corba.HostDirectory;
import org.fdnet.corba.HostProcess;
import org.fdnet.corba.IdlMapping;
import org.fdnet.corba.LinkSettings;
import org.fdnet.corba.LocalNetwork;
import org.fdnet.corba.NamingService;
import org.fdnet.corba.OrbSettings;
import org.fdnet.corba.OutboundLink;
import org.fdnet.corba.idl.Host;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;

/**
 * The three hosts of {@code fdnet bench corba}, wired with the same Host operations {@code fdnet run} uses:
 *
 * <pre>
 *   bench-a (this JVM)            bench-b (child JVM)            bench-probe (this JVM)
 *   Data bench/src ──link 1──▶ stand-in bench/src ──link 2──▶ stand-in bench/out ──▶ observer
 * </pre>
 *
 * A value written on bench-a crosses to another process and comes back to the observer: two host
 * boundaries, as a request and its reply cross two in the bare two-way call.
 */
final class BenchTopology implements AutoCloseable {
    private static final NodeRef SRC = new NodeRef("bench", "src");
    private static final NodeRef OUT = new NodeRef("bench", "out");

    private final FdnetChildProcess child;
    private final HostProcess a;
    private final HostProcess probe;
    private final LocalNetwork aNetwork;
    private final LocalNetwork probeNetwork;
    private final Host b;

    private BenchTopology(FdnetChildProcess child, HostProcess a, LocalNetwork aNetwork, HostProcess probe,
                          LocalNetwork probeNetwork, Host b) {
        this.child = child;
        this.a = a;
        this.aNetwork = aNetwork;
        this.probe = probe;
        this.probeNetwork = probeNetwork;
        this.b = b;
    }

    static BenchTopology start(LinkSettings links) {
        int namingPort = FdnetChildProcess.freePort();
        String corbaloc = NamingService.start(OrbSettings.defaults().withPort(namingPort), 15_000);
        FdnetChildProcess child = FdnetChildProcess.start("host bench-b",
                List.of("host", "--name", "bench-b", "--naming", corbaloc), " ready", 60_000);
        HostProcess a = null;
        HostProcess probe = null;
        try {
            OrbSettings settings = OrbSettings.defaults().withNaming(corbaloc);
            LocalNetwork aNetwork = new DataOnlyNetwork();
            LocalNetwork probeNetwork = new DataOnlyNetwork();
            a = HostProcess.start("bench-a", settings, aNetwork, new ClassPolicy(List.of()), links);
            probe = HostProcess.start("bench-probe", settings, probeNetwork, new ClassPolicy(List.of()), links);
            Host b = HostDirectory.connect(a.orb()).find("bench-b")
                    .orElseThrow(() -> new IllegalStateException("bench-b did not register"));
            wire(a.reference(), b, probe.reference(), links.window());
            return new BenchTopology(child, a, aNetwork, probe, probeNetwork, b);
        } catch (RuntimeException | org.omg.CORBA.UserException e) {
            if (probe != null) {
                probe.close();
            }
            if (a != null) {
                a.close();
            }
            child.close();
            throw new IllegalStateException("cannot set up the benchmark: " + e, e);
        }
    }

    private static void wire(Host a, Host b, Host probe, int window) throws org.omg.CORBA.UserException {
        a.createNode(IdlMapping.spec(SRC.module(), NodeInfo.data(SRC.node(), "org.fdnet.bench.LongData")));
        b.createStandIn(IdlMapping.spec(SRC.module(), NodeInfo.data(SRC.node(), "org.fdnet.bench.LongData")), "bench-a");
        probe.createNode(IdlMapping.spec(OUT.module(), NodeInfo.data(OUT.node(), "org.fdnet.bench.LongData")));
        b.acceptLink(1, IdlMapping.id(SRC), "bench-a");
        a.forward(1, IdlMapping.id(SRC), b, "bench-b", window);
        probe.acceptLink(2, IdlMapping.id(OUT), "bench-b");
        b.forward(2, IdlMapping.id(SRC), probe, "bench-probe", window);
    }

    Host remoteHost() {
        return b;
    }

    /** A local write on bench-a, as a sensor or Relation there would make it. */
    void write(long value) {
        aNetwork.write(SRC, value);
    }

    AutoCloseable observeArrivals(LocalNetwork.ValueObserver observer) {
        return probeNetwork.observe(OUT, observer);
    }

    String hopPath() {
        return "write on A -> Data on B -> back on A";
    }

    String describe() {
        return "bench-a:bench/src -> bench-b:bench/src -> bench-probe:bench/out";
    }

    String[] linkReport() {
        return a.servant().outboundLinks().stream()
                .map(l -> l.description() + ": " + l.acknowledged() + " acknowledged, " + l.lost() + " lost")
                .toArray(String[]::new);
    }

    @Override
    public void close() {
        probe.close();
        a.close();
        child.close();
    }
}

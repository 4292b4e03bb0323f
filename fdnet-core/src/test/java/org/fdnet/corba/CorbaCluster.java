package org.fdnet.corba;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fdnet.corba.idl.Host;

/**
 * A naming service and FDNet hosts as real child processes on 127.0.0.1 (free ports), plus an ORB in the
 * test JVM to talk to them. Tests create one per test and {@link #close()} it in {@code @AfterEach}:
 * every process is ended, forcibly if it does not stop.
 */
final class CorbaCluster implements AutoCloseable {
    private final List<AutoCloseable> toClose = new ArrayList<>();
    private final Map<String, FdnetChildProcess> hosts = new LinkedHashMap<>();
    private final Map<String, List<String>> hostArgs = new LinkedHashMap<>();
    private FdnetChildProcess naming;
    private String corbaloc;
    private OrbRuntime orb;
    private HostDirectory directory;

    static CorbaCluster start() {
        CorbaCluster c = new CorbaCluster();
        int port = FdnetChildProcess.freePort();
        c.naming = FdnetChildProcess.start("naming", List.of("naming", "--port", Integer.toString(port)),
                "fdnet naming ready", 60_000);
        c.corbaloc = OrbSettings.namingCorbaloc(OrbSettings.LOOPBACK, port);
        c.orb = OrbRuntime.start(OrbSettings.defaults().withNaming(c.corbaloc).withCallTimeoutMillis(5_000));
        c.directory = HostDirectory.connect(c.orb);
        return c;
    }

    /** Starts {@code fdnet host --name NAME} with extra arguments and returns its reference. */
    Host startHost(String name, String... extraArgs) {
        List<String> args = new ArrayList<>(List.of("host", "--name", name, "--naming", corbaloc));
        args.addAll(List.of(extraArgs));
        hostArgs.put(name, args);
        FdnetChildProcess p = FdnetChildProcess.start("host " + name, args, "fdnet host " + name + " ready", 60_000);
        hosts.put(name, p);
        return host(name);
    }

    /** Kills a host like {@code kill -9}: no shutdown hook, its name stays bound to a dead reference. */
    void kill(String name) {
        hosts.get(name).kill();
    }

    Host restart(String name) {
        FdnetChildProcess p = FdnetChildProcess.start("host " + name, hostArgs.get(name),
                "fdnet host " + name + " ready", 60_000);
        hosts.put(name, p);
        return host(name);
    }

    Host host(String name) {
        return directory.find(name).orElseThrow(() -> new AssertionError("host " + name + " is not registered"));
    }

    /** An FDNet host in the test JVM (for observing values), closed with the cluster. */
    HostProcess startLocalHost(String name, LocalNetwork network, LinkSettings links) {
        HostProcess h = HostProcess.start(name, OrbSettings.defaults().withNaming(corbaloc), network,
                new ClassPolicy(List.of()), links);
        toClose.add(h);
        return h;
    }

    String corbaloc() {
        return corbaloc;
    }

    HostDirectory directory() {
        return directory;
    }

    OrbRuntime orb() {
        return orb;
    }

    List<String> output(String host) {
        return hosts.get(host).output();
    }

    @Override
    public void close() {
        for (int i = toClose.size() - 1; i >= 0; i--) {
            try {
                toClose.get(i).close();
            } catch (Exception e) {
                System.err.println("cleanup: " + e);
            }
        }
        hosts.values().forEach(FdnetChildProcess::close);
        if (orb != null) {
            orb.close();
        }
        if (naming != null) {
            naming.close();
        }
    }
}

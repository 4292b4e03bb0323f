package org.fdnet.logger.soak;

import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * Injects one planned fault into the soak's processes and returns once it is over: the process is back, the database
 * up, the links clean — for the naming service, once every host has registered in it again.
 */
final class FaultInjector {
    private final SoakCluster cluster;
    private static final long REGISTER_TIMEOUT_MILLIS = 30_000;
    private final Path linkSwitch;
    private final List<String> hosts;

    FaultInjector(SoakCluster cluster, Path linkSwitch, List<String> hosts) {
        this.cluster = cluster;
        this.linkSwitch = linkSwitch;
        this.hosts = hosts;
    }

    /** Lines in which the host said it registered again in a restarted naming service ({@code HostProcess}). */
    private long registeredAgain(String host) {
        return cluster.process(host).output().stream().filter(l -> l.contains("registered again")).count();
    }

    InjectedFault inject(FaultPlan.Planned fault) throws IOException, InterruptedException {
        long at = System.currentTimeMillis();
        switch (fault.kind()) {
            case LINK_FAULTS -> {
                SoakCommand.writeSwitch(linkSwitch, FaultPlan.linkFaultsOn());
                Thread.sleep(fault.lengthMillis());
                SoakCommand.writeSwitch(linkSwitch, "");
            }
            case HOST_KILL, LOGGER_KILL -> {
                String process = fault.kind() == FaultKind.HOST_KILL ? fault.target() : "logger";
                cluster.kill(process);
                cluster.startProcess(process);
            }
            case NAMING_RESTART -> {
                Map<String, Long> before = new HashMap<>();
                for (String host : hosts) {
                    before.put(host, registeredAgain(host));
                }
                cluster.kill("naming");
                cluster.startProcess("naming");
                long deadline = System.currentTimeMillis() + REGISTER_TIMEOUT_MILLIS;
                for (String host : hosts) {
                    while (registeredAgain(host) <= before.get(host) && System.currentTimeMillis() < deadline) {
                        Thread.sleep(50);
                    }
                }
            }
            case DATABASE_STOP -> {
                cluster.stopDatabase();
                Thread.sleep(fault.lengthMillis());
                cluster.startDatabase();
            }
            default -> throw new IllegalStateException("fault kind " + fault.kind() + " has no injector");
        }
        return new InjectedFault(fault.kind(), fault.target(), at, System.currentTimeMillis(), -1);
    }
}

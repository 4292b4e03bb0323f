package org.fdnet.logger.soak;

import java.io.IOException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import org.fdnet.apart.ApartRig;

/**
 * Injects one planned fault into the soak's processes or their links and returns once it is over: the process is back,
 * the database up, the links clean or healed — for the naming service, once every host has registered in it again.
 */
final class FaultInjector {
    private final SoakCluster cluster;
    private static final long REGISTER_TIMEOUT_MILLIS = 30_000;
    private final Path linkSwitch;
    private final List<String> hosts;
    /** The rig whose links the network kinds are put on; {@code null} when the processes are not apart. */
    private final ApartRig rig;

    FaultInjector(SoakCluster cluster, Path linkSwitch, List<String> hosts, ApartRig rig) {
        this.cluster = cluster;
        this.linkSwitch = linkSwitch;
        this.hosts = hosts;
        this.rig = rig;
    }

    /** Lines in which the host said it registered again in a restarted naming service ({@code HostProcess}). */
    private long registeredAgain(String host) {
        return cluster.process(host).output().stream().filter(l -> l.contains("registered again")).count();
    }

    private ApartRig rig() {
        if (rig == null) {
            throw new IllegalStateException("network faults need hosts that are apart (fdnet soak --apart)");
        }
        return rig;
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
            case HOST_PARTITION, LOGGER_PARTITION, NAMING_PARTITION -> {
                rig().blackhole(fault.target());
                Thread.sleep(fault.lengthMillis());
                rig().heal(fault.target());
            }
            case THROTTLE -> {
                rig().throttle(fault.target(), FaultPlan.THROTTLE_KBIT_PER_SECOND);
                Thread.sleep(fault.lengthMillis());
                rig().clear(fault.target());
            }
            case LOSS -> {
                for (String host : rig().hosts()) {
                    rig().loss(host, FaultPlan.LOSS_PERCENT);
                }
                Thread.sleep(fault.lengthMillis());
                for (String host : rig().hosts()) {
                    rig().loss(host, 0);
                }
            }
            default -> throw new IllegalStateException("fault kind " + fault.kind() + " has no injector");
        }
        return new InjectedFault(fault.kind(), fault.target(), at, System.currentTimeMillis(), -1);
    }
}

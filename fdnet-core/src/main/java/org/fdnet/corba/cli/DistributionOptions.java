package org.fdnet.corba.cli;

import org.fdnet.corba.DistributedRun;
import org.fdnet.corba.OrbSettings;
import org.fdnet.netinfo.NetworkInfo;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * The options {@code fdnet run} takes for networks whose nodes name other hosts. A network whose nodes all live
 * on this machine runs as before.
 */
public final class DistributionOptions {
    @Mixin
    NamingOptions naming = new NamingOptions();

    @Option(names = "--as", paramLabel = "HOST",
            description = "the host name of this process in a distributed run (default: run-PID)")
    String localHostName;

    /**
     * Applies {@code --tls} and refuses a non-loopback {@code --bind} or control address without TLS or {@code --insecure};
     * before any connection of the run (its logger client too) is made.
     */
    public void secure(String controlAddress) {
        naming.secure("this run's host");
        naming.tls.requireSafeBind("the network's control object", controlAddress);
    }

    /** Whether {@code definition} must be distributed (a node names another host). */
    public boolean appliesTo(NetworkInfo definition) {
        return DistributedRun.spansHosts(definition);
    }

    /** The ORB settings of this process's host: naming service and listening address. */
    public OrbSettings orbSettings() {
        return naming.orbSettings();
    }

    /** This process's host name in a distributed run. */
    public String localHostName() {
        return localHostName != null ? localHostName : "run-" + ProcessHandle.current().pid();
    }

    /** Uses the naming service at {@code corbaloc} (what {@code --naming} sets). */
    public void naming(String corbaloc) {
        naming.corbaloc = corbaloc;
    }
}

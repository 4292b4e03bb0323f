package org.fdnet.corba.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.time.Duration;
import java.util.List;
import org.fdnet.corba.DistributedRun;
import org.fdnet.event.EventSink;
import org.fdnet.netinfo.NetworkInfo;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;

/**
 * The options {@code fdnet run} takes for networks whose nodes name other hosts, and the switch to the
 * distributed run. A network whose nodes all live on this machine runs as before.
 */
public final class DistributionOptions {
    @Mixin
    NamingOptions naming;

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

    public int run(Path file, NetworkInfo definition, Duration duration, List<Path> allowedRoots, List<String> sets,
                   List<String> loads, String loggerAddress, EventSink events, PrintWriter out, PrintWriter err)
            throws InterruptedException {
        String name = localHostName != null ? localHostName : "run-" + ProcessHandle.current().pid();
        return DistributedRun.run(new DistributedRun.Request(file, definition, duration, allowedRoots,
                naming.corbaloc(), name, sets, loads, loggerAddress), events, out, err);
    }
}

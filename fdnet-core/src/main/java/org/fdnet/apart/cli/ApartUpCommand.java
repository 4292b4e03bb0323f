package org.fdnet.apart.cli;

import java.io.PrintWriter;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import org.fdnet.apart.ApartRig;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code fdnet apart up}: makes the rig, prints its hosts and addresses, and keeps it until stopped. */
@Command(name = "up", mixinStandardHelpOptions = true,
        description = "Make a rig with these hosts, print each one's address and how to run on it, and keep it until"
                + " Ctrl-C (or fdnet apart down), which removes everything it made and ends what runs on its hosts.")
public final class ApartUpCommand implements Callable<Integer> {
    @Option(names = "--hosts", required = true, split = ",", paramLabel = "HOST",
            description = "the hosts, e.g. naming,flyer,crawler,logger,viewer: each gets a namespace and an address")
    List<String> hosts;

    @Mixin
    RigNameOption rigName;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        ApartRig rig;
        try {
            if (ApartRig.find(rigName.name).isPresent()) {
                throw new IllegalStateException("a rig named " + rigName.name + " is already up (fdnet apart status);"
                        + " remove it with fdnet apart down, or give this one another --name");
            }
            rig = ApartRig.create(rigName.name, hosts);
        } catch (IllegalArgumentException | IllegalStateException e) {
            spec.commandLine().getErr().println("fdnet apart up: " + e.getMessage());
            return 1;
        }
        PrintWriter out = spec.commandLine().getOut();
        CountDownLatch removed = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            out.println("fdnet apart: removing rig " + rig.rigNamespace() + " …");
            rig.close();
            out.println("fdnet apart: removed");
            out.flush();
            removed.countDown();
        }, "fdnet-apart-down"));
        RigTable.print(rig, out);
        out.println();
        out.println("run on a host:  fdnet apart exec HOST -- COMMAND…   (e.g. fdnet apart exec " + hosts.get(0)
                + " -- bin/fdnet naming --bind " + rig.address(hosts.get(0)).getHostAddress() + " --tls …)");
        out.println("faults:         fdnet apart fault HOST blackhole|heal|loss PERCENT|throttle KBIT|clear");
        out.println("fdnet apart up ready: rig " + rig.rigNamespace() + " on " + rig.subnet()
                + "; Ctrl-C removes it");
        out.flush();
        try {
            removed.await();
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
        return 0;
    }
}

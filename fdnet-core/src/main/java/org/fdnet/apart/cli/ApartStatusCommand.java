package org.fdnet.apart.cli;

import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code fdnet apart status}: the rig that is up, its hosts, addresses and faults. */
@Command(name = "status", mixinStandardHelpOptions = true,
        description = "Print the rig that is up: each host's address, namespace and the faults on its link.")
public final class ApartStatusCommand implements Callable<Integer> {
    @Mixin
    RigNameOption rigName;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        try {
            RigTable.print(rigName.running(), System.out);
            return 0;
        } catch (IllegalArgumentException | IllegalStateException e) {
            spec.commandLine().getErr().println("fdnet apart status: " + e.getMessage());
            return 1;
        }
    }
}

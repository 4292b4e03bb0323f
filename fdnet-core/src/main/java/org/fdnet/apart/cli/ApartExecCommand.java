package org.fdnet.apart.cli;

import java.io.IOException;
import java.util.List;
import java.util.concurrent.Callable;
import org.fdnet.apart.ApartRig;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fdnet apart exec}: runs a command on one host of the rig that is up. */
@Command(name = "exec", mixinStandardHelpOptions = true,
        description = "Run COMMAND on HOST of the rig that is up: it sees only that host's address and its own"
                + " loopback. Exits with COMMAND's exit code.")
public final class ApartExecCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "HOST", description = "the host to run on")
    String host;

    @Parameters(index = "1..*", paramLabel = "COMMAND", arity = "1..*",
            description = "the command and its arguments (put -- before it when it has options of its own)")
    List<String> command;

    @Mixin
    RigNameOption rigName;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        List<String> argv;
        try {
            ApartRig rig = rigName.running();
            argv = rig.command(host, command);
        } catch (IllegalArgumentException | IllegalStateException e) {
            spec.commandLine().getErr().println("fdnet apart exec: " + e.getMessage());
            return 1;
        }
        try {
            Process p = new ProcessBuilder(argv).inheritIO().start();
            return p.waitFor();
        } catch (IOException e) {
            spec.commandLine().getErr().println("fdnet apart exec: cannot run " + String.join(" ", command) + ": "
                    + e.getMessage());
            return 1;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 130;
        }
    }
}

package org.fdnet.apart.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.util.List;
import org.fdnet.apart.ApartRig;
import picocli.CommandLine.Command;
import picocli.CommandLine.Parameters;

/** {@code fdnet apart exec}: runs a command on one host of the rig that is up. */
@Command(name = "exec", mixinStandardHelpOptions = true,
        description = "Run COMMAND on HOST of the rig that is up: it sees only that host's address and its own"
                + " loopback. Exits with COMMAND's exit code.")
public final class ApartExecCommand extends OnTheRigThatIsUp {
    @Parameters(index = "0", paramLabel = "HOST", description = "the host to run on")
    String host;

    @Parameters(index = "1..*", paramLabel = "COMMAND", arity = "1..*",
            description = "the command and its arguments (put -- before it when it has options of its own)")
    List<String> command;

    @Override
    int on(ApartRig rig, PrintWriter out) {
        try {
            return new ProcessBuilder(rig.command(host, command)).inheritIO().start().waitFor();
        } catch (IOException e) {
            throw new IllegalStateException("cannot run " + String.join(" ", command) + ": " + e.getMessage(), e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 130;
        }
    }
}

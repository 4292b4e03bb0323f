package org.fdnet.apart.cli;

import java.io.PrintWriter;
import java.util.concurrent.Callable;
import org.fdnet.apart.ApartRig;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * A subcommand that works on the rig that is up under {@code --name}: a refusal (no such rig, host or fault) is one
 * line {@code fdnet apart SUBCOMMAND: why} and exit 1.
 */
abstract class OnTheRigThatIsUp implements Callable<Integer> {
    @Mixin
    RigNameOption rigName;

    @Spec
    CommandSpec spec;

    @Override
    public final Integer call() {
        try {
            return on(rigName.running(), spec.commandLine().getOut());
        } catch (IllegalArgumentException | IllegalStateException e) {
            spec.commandLine().getErr().println("fdnet apart " + spec.name() + ": " + e.getMessage());
            return 1;
        }
    }

    /**
     * Does the subcommand's work.
     *
     * @param out where it reports
     * @return the exit code
     */
    abstract int on(ApartRig rig, PrintWriter out);
}

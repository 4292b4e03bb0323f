package org.fdnet.apart.cli;

import java.util.List;
import java.util.concurrent.Callable;
import org.fdnet.apart.ApartRig;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code fdnet apart sweep}: removes what rigs whose process was killed left behind. */
@Command(name = "sweep", mixinStandardHelpOptions = true,
        description = "Remove the namespaces of rigs named NAME whose process is gone (killed before it could clean"
                + " up); a rig that is up is left alone.")
public final class ApartSweepCommand implements Callable<Integer> {
    @Mixin
    RigNameOption rigName;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        try {
            List<String> removed = ApartRig.sweep(rigName.name);
            spec.commandLine().getOut().println("fdnet apart sweep: " + (removed.isEmpty() ? "nothing left behind"
                    : "removed " + String.join(", ", removed)));
            return 0;
        } catch (IllegalArgumentException | IllegalStateException e) {
            spec.commandLine().getErr().println("fdnet apart sweep: " + e.getMessage());
            return 1;
        }
    }
}

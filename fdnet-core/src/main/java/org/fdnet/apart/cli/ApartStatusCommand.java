package org.fdnet.apart.cli;

import java.io.PrintWriter;
import org.fdnet.apart.ApartRig;
import picocli.CommandLine.Command;

/** {@code fdnet apart status}: the rig that is up, its hosts, addresses and faults. */
@Command(name = "status", mixinStandardHelpOptions = true,
        description = "Print the rig that is up: each host's address, namespace and the faults on its link.")
public final class ApartStatusCommand extends OnTheRigThatIsUp {
    @Override
    int on(ApartRig rig, PrintWriter out) {
        RigTable.print(rig, out);
        return 0;
    }
}

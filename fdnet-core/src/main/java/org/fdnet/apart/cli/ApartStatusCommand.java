package org.fdnet.apart.cli;

import org.fdnet.apart.ApartRig;
import picocli.CommandLine.Command;

/** {@code fdnet apart status}: the rig that is up, its hosts, addresses and faults. */
@Command(name = "status", mixinStandardHelpOptions = true,
        description = "Print the rig that is up: each host's address, namespace and the faults on its link.")
public final class ApartStatusCommand extends OnTheRigThatIsUp {
    @Override
    int on(ApartRig rig) {
        RigTable.print(rig, System.out);
        return 0;
    }
}

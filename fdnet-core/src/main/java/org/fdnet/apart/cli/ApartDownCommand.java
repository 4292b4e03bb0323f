package org.fdnet.apart.cli;

import java.io.PrintWriter;
import java.util.Optional;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.fdnet.apart.ApartRig;
import picocli.CommandLine.Command;

/** {@code fdnet apart down}: stops the process that keeps the rig up, which removes it. */
@Command(name = "down", mixinStandardHelpOptions = true,
        description = "Remove the rig that is up: its fdnet apart up is stopped, which ends what runs on its hosts"
                + " and removes every namespace, link and rule it made.")
public final class ApartDownCommand extends OnTheRigThatIsUp {
    private static final long WAIT_SECONDS = 30;

    @Override
    int on(ApartRig rig, PrintWriter out) {
        Optional<ProcessHandle> owner = ProcessHandle.of(rig.ownerPid());
        if (owner.isPresent()) {
            owner.get().destroy();
            try {
                owner.get().onExit().get(WAIT_SECONDS, TimeUnit.SECONDS);
            } catch (TimeoutException | ExecutionException e) {
                throw new IllegalStateException("the rig's process " + rig.ownerPid() + " did not end in "
                        + WAIT_SECONDS + " s", e);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                return 130;
            }
        }
        ApartRig.sweep(rigName.name);
        out.println("fdnet apart down: rig " + rig.rigNamespace() + " removed");
        return 0;
    }
}

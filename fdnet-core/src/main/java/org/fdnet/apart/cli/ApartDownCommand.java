package org.fdnet.apart.cli;

import java.util.Optional;
import java.util.concurrent.Callable;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import org.fdnet.apart.ApartRig;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code fdnet apart down}: stops the process that keeps the rig up, which removes it. */
@Command(name = "down", mixinStandardHelpOptions = true,
        description = "Remove the rig that is up: its fdnet apart up is stopped, which ends what runs on its hosts"
                + " and removes every namespace, link and rule it made.")
public final class ApartDownCommand implements Callable<Integer> {
    private static final long WAIT_SECONDS = 30;

    @Mixin
    RigNameOption rigName;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        try {
            ApartRig rig = rigName.running();
            Optional<ProcessHandle> owner = ProcessHandle.of(rig.ownerPid());
            if (owner.isPresent()) {
                owner.get().destroy();
                owner.get().onExit().get(WAIT_SECONDS, TimeUnit.SECONDS);
            }
            ApartRig.sweep(rigName.name);
            System.out.println("fdnet apart down: rig " + rig.rigNamespace() + " removed");
            return 0;
        } catch (IllegalArgumentException | IllegalStateException e) {
            spec.commandLine().getErr().println("fdnet apart down: " + e.getMessage());
            return 1;
        } catch (TimeoutException | ExecutionException e) {
            spec.commandLine().getErr().println("fdnet apart down: the rig's process did not end in " + WAIT_SECONDS
                    + " s");
            return 1;
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return 130;
        }
    }
}

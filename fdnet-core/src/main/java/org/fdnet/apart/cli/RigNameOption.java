package org.fdnet.apart.cli;

import java.util.Optional;
import org.fdnet.apart.ApartRig;
import picocli.CommandLine.Option;

/** {@code --name}: which rig, of those that may be up on this machine at once. */
final class RigNameOption {
    @Option(names = "--name", paramLabel = "NAME", defaultValue = ApartCommand.DEFAULT_NAME,
            description = "the rig's name: its namespaces are NAME-PID and NAME-PID-HOST (default: ${DEFAULT-VALUE})")
    String name;

    /**
     * The rig that is up under this name.
     *
     * @throws IllegalStateException saying how to start one when none is up
     */
    ApartRig running() {
        Optional<ApartRig> rig = ApartRig.find(name);
        return rig.orElseThrow(() -> new IllegalStateException("no rig named " + name + " is up: start one with"
                + " fdnet apart up --hosts A,B,…" + (name.equals(ApartCommand.DEFAULT_NAME) ? "" : " --name " + name)));
    }
}

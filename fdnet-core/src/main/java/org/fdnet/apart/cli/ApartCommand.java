package org.fdnet.apart.cli;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code fdnet apart}: hosts on addresses of their own, on one machine, for trying a network across them by hand. */
@Command(name = "apart", mixinStandardHelpOptions = true,
        description = "Put hosts on addresses of their own on this machine (a network namespace each, joined on a"
                + " bridge; root only), run FDNet processes on them and put faults on their links: a silent"
                + " partition, random loss, a slow link.",
        footer = {"", "Example:",
                "  fdnet apart up --hosts naming,flyer,crawler     (Ctrl-C removes it all)",
                "  fdnet apart exec flyer -- bin/fdnet host --name flyer --bind ADDRESS …",
                "  fdnet apart fault flyer blackhole             (then: heal)",
                "  fdnet apart status"},
        subcommands = {ApartUpCommand.class, ApartExecCommand.class, ApartFaultCommand.class, ApartStatusCommand.class,
                ApartDownCommand.class, ApartSweepCommand.class})
public final class ApartCommand implements Runnable {
    /** The name a rig has unless {@code --name} gives another. */
    static final String DEFAULT_NAME = "apart";

    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }
}

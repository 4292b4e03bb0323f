package org.fdnet.cli;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code fdnet new}: start a project of your own from FDNet's starter. */
@Command(name = "new", mixinStandardHelpOptions = true,
        description = "Start a project of your own from one of FDNet's starters.",
        subcommands = {NewNodesCommand.class})
public final class NewCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }
}

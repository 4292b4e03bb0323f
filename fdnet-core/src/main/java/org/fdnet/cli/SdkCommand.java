package org.fdnet.cli;

import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/** {@code fdnet sdk}: FDNet as artifacts a Java build depends on. */
@Command(name = "sdk", mixinStandardHelpOptions = true,
        description = "FDNet as a Java SDK: the artifacts, a BOM, the starter archetype and the test kits a project "
                + "of your own builds on (docs/build-your-own-nodes.md).",
        subcommands = {SdkInstallCommand.class})
public final class SdkCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }
}

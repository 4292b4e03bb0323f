package org.fdnet.run;

import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code fdnet run FILE}: runs a network — on this machine, or over the hosts its nodes name — as one
 * {@link NetworkRun}. Exit 0 when it ran, 1 for a bad file or a network that cannot start, 2 for a bad or refused
 * option.
 */
@Command(name = "run", mixinStandardHelpOptions = true,
        description = {"Run a network; print progress each second and a summary at the end.",
                "Nodes whose <host> names another host run there (fdnet host --name H); see docs/explanation/distribution.md."
                        + " Every option works across hosts, or is refused by name.",
                "While it runs it takes commands on standard input: load, unload, hold, resume MODULE;"
                        + " set [MODULE/]NODE/PARAM=VALUE; send [MODULE/]NODE=VALUE; help.",
                "It publishes its control object for fdnet control NAME and fdnet hi --attach NAME (docs/how-to/live-changes.md)."})
public final class RunCommand implements Callable<Integer> {
    @Parameters(paramLabel = "FILE", description = "the .fdn network definition")
    Path file;

    @Mixin
    RunOptions options;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws InterruptedException {
        return new NetworkRun(file, options, spec.commandLine().getOut(), spec.commandLine().getErr(), System.in).run();
    }
}

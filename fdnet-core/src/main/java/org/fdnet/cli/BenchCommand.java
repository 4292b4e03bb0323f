package org.fdnet.cli;

import org.fdnet.cli.spi.CommandProvider;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * {@code fdnet bench}: the group of benchmarks. Every benchmark prints its figures and a baseline
 * measured in the same run (the machine is shared and noisy: the ratios are what hold). The benchmarks themselves
 * live in the bench modules and come in through {@link CommandProvider#benchmarks()}: this command names none.
 */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = "Benchmarks; each prints its figures beside a baseline measured in the same run.")
public final class BenchCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }
}

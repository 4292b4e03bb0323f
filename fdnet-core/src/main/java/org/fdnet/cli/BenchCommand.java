package org.fdnet.cli;

import org.fdnet.bench.LoadBenchmark;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * {@code fdnet bench}: the group of benchmarks. Every benchmark prints its figures and a baseline
 * measured in the same run (the machine is shared and noisy: the ratios are what hold).
 */
@Command(name = "bench", mixinStandardHelpOptions = true,
        description = "Benchmarks; each prints its figures beside a baseline measured in the same run.",
        subcommands = LoadBenchmark.class)
public final class BenchCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }
}

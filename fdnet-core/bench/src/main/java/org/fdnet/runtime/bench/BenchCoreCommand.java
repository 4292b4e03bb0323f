package org.fdnet.runtime.bench;

import java.util.concurrent.Callable;
import org.fdnet.runtime.bench.CoreBenchmark;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/** {@code fdnet bench core}: hop latency, chain throughput and fan-out of the runtime, beside plain Java. */
@Command(name = "core", mixinStandardHelpOptions = true,
        description = "In-process runtime: hop latency p50/p99, 10-Relation chain throughput, 1->100 fan-out; "
                + "each beside plain Java calls doing the same work.")
public final class BenchCoreCommand implements Callable<Integer> {
    @Option(names = "--hops", defaultValue = "500000", description = "measured hops (default: ${DEFAULT-VALUE})")
    int hops;

    @Option(names = "--warmup", defaultValue = "200000", description = "warm-up hops (default: ${DEFAULT-VALUE})")
    int warmup;

    @Option(names = "--logger", paramLabel = "HOST:PORT",
            description = "also run the hop with a logger client attached, sending its events to this running logger")
    String logger;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        new CoreBenchmark(spec.commandLine().getOut(), hops, warmup, logger).run();
        return 0;
    }
}

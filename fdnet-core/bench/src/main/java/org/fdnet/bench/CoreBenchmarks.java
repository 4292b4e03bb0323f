package org.fdnet.bench;

import java.util.List;
import org.fdnet.cli.spi.CommandProvider;
import org.fdnet.corba.bench.CorbaBenchmark;
import org.fdnet.runtime.bench.BenchCoreCommand;

/**
 * Adds the core's benchmarks to {@code fdnet bench}: {@code load} (network files and queries), {@code core} (the
 * engine's hop latency) and {@code corba} (hops across hosts). They live in this bench module, never in the
 * fdnet-core jar; bin/fdnet puts the module on its class path.
 */
public final class CoreBenchmarks implements CommandProvider {
    @Override
    public List<Object> benchmarks() {
        return List.of(new LoadBenchmark(), new BenchCoreCommand(), new CorbaBenchmark());
    }
}

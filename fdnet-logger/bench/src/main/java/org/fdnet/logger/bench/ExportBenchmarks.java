package org.fdnet.logger.bench;

import java.util.List;
import org.fdnet.cli.spi.CommandProvider;

/** Adds {@code fdnet bench export}. */
public final class ExportBenchmarks implements CommandProvider {
    @Override
    public List<Object> benchmarks() {
        return List.of(new BenchExportCommand());
    }
}

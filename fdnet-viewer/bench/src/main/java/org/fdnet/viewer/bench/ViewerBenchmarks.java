package org.fdnet.viewer.bench;

import java.util.List;
import org.fdnet.cli.spi.CommandProvider;

/** Adds {@code fdnet bench viewer}: history queries while a writer drains, over a throwaway logger. */
public final class ViewerBenchmarks implements CommandProvider {
    @Override
    public List<Object> benchmarks() {
        return List.of(new BenchViewerCommand());
    }
}

package org.fdnet.roq.bench;

import java.util.List;
import org.fdnet.cli.spi.CommandProvider;

/** Adds {@code fdnet bench rt}, {@code fdnet bench sim} and {@code fdnet bench roq}. */
public final class RoqBenchmarks implements CommandProvider {
    @Override
    public List<Object> benchmarks() {
        return List.of(new BenchRtCommand(), new BenchSimCommand(), new BenchRoqCommand());
    }
}

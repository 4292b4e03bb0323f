package org.fdnet.logger.bench;

import java.util.List;
import org.fdnet.cli.spi.CommandProvider;
import org.fdnet.logger.soak.SoakCommand;

/**
 * Adds the logger's rigs: {@code fdnet bench logger} and {@code fdnet soak} (the fault-injection rig over a whole
 * network). They live in fdnet-logger/bench, never in the logger's jar.
 */
public final class LoggerBenchmarks implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new SoakCommand());
    }

    @Override
    public List<Object> benchmarks() {
        return List.of(new BenchLoggerCommand());
    }
}

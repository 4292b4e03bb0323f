package org.fdnet.logger.cli;

import java.util.List;
import org.fdnet.cli.CommandProvider;

/** Adds {@code fdnet logger} and {@code fdnet bench logger}. */
public final class LoggerCommandProvider implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new LoggerCommand());
    }

    @Override
    public List<Object> benchmarks() {
        return List.of(new BenchLoggerCommand());
    }
}

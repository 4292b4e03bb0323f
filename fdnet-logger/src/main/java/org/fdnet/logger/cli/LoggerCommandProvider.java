package org.fdnet.logger.cli;

import java.util.List;
import org.fdnet.cli.CommandProvider;
import org.fdnet.logger.soak.SoakCommand;

/** Adds {@code fdnet logger}, {@code fdnet soak} and {@code fdnet bench logger}. */
public final class LoggerCommandProvider implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new LoggerCommand(), new SoakCommand());
    }

    @Override
    public List<Object> benchmarks() {
        return List.of(new BenchLoggerCommand());
    }
}

package org.fdnet.logger.cli;

import java.util.List;
import org.fdnet.cli.spi.CommandProvider;

/** Adds {@code fdnet logger} and {@code fdnet export} ({@code bench logger} and {@code soak} are fdnet-logger/bench's). */
public final class LoggerCommands implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new LoggerCommand(), new ExportCommand());
    }
}

package org.fdnet.runtime.cli;

import java.util.List;
import org.fdnet.cli.CommandProvider;

/** Adds {@code fdnet bench core} to the command line ({@code fdnet run} is {@code org.fdnet.run}'s). */
public final class RuntimeCommands implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of();
    }

    @Override
    public List<Object> benchmarks() {
        return List.of(new BenchCoreCommand());
    }
}

package org.fdnet.runtime.cli;

import java.util.List;
import org.fdnet.cli.CommandProvider;

/** Adds {@code fdnet run} and {@code fdnet bench core} to the command line. */
public final class RuntimeCommands implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new RunCommand());
    }

    @Override
    public List<Object> benchmarks() {
        return List.of(new BenchCoreCommand());
    }
}

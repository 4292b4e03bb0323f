package org.fdnet.run;

import java.util.List;
import org.fdnet.cli.spi.CommandProvider;

/** Adds {@code fdnet run} to the command line. */
public final class RunCommands implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new RunCommand());
    }
}

package org.fdnet.corba.cli;

import java.util.List;
import org.fdnet.cli.spi.CommandProvider;

/** Adds {@code naming}, {@code host} and {@code control} to {@code fdnet} ({@code bench corba} is fdnet-core/bench's). */
public final class CorbaCommandProvider implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new NamingCommand(), new HostCommand(), new ControlCommand());
    }
}

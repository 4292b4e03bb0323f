package org.fdnet.corba.cli;

import java.util.List;
import org.fdnet.cli.CommandProvider;
import org.fdnet.corba.bench.CorbaBenchmark;

/** Adds {@code naming}, {@code host}, {@code control} and {@code bench corba} to {@code fdnet}. */
public final class CorbaCommandProvider implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new NamingCommand(), new HostCommand(), new ControlCommand());
    }

    @Override
    public List<Object> benchmarks() {
        return List.of(new CorbaBenchmark());
    }
}

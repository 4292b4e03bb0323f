package org.fdnet.roq.cli;

import java.util.List;
import org.fdnet.cli.spi.CommandProvider;

/** Adds {@code fdnet sim} and {@code fdnet demo} (the benchmarks are roq-sim/bench's). */
public final class RoqCommandProvider implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new SimCommand(), new DemoCommand());
    }
}

package org.fdnet.hi.cli;

import java.util.List;
import org.fdnet.cli.CommandProvider;

/** Adds {@code fdnet hi} and {@code fdnet bench hi}. */
public final class HiCommandProvider implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new HiCommand());
    }

    @Override
    public List<Object> benchmarks() {
        return List.of(new BenchHiCommand());
    }
}

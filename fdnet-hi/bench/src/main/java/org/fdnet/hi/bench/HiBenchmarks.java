package org.fdnet.hi.bench;

import java.util.List;
import org.fdnet.cli.spi.CommandProvider;

/** Adds {@code fdnet bench hi}: the editor on a generated network. */
public final class HiBenchmarks implements CommandProvider {
    @Override
    public List<Object> benchmarks() {
        return List.of(new BenchHiCommand());
    }
}

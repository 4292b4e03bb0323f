package org.fdnet.hi.cli;

import java.util.List;
import org.fdnet.cli.spi.CommandProvider;

/** Adds {@code fdnet hi} ({@code bench hi} is fdnet-hi/bench's). */
public final class HiCommandProvider implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new HiCommand());
    }
}

package org.fdnet.apart.cli;

import java.util.List;
import org.fdnet.cli.spi.CommandProvider;

/** Adds {@code fdnet apart} to the command line. */
public final class ApartCommandProvider implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new ApartCommand());
    }
}

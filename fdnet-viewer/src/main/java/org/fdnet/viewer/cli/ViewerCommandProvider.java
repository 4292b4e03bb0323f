package org.fdnet.viewer.cli;

import java.util.List;
import org.fdnet.cli.spi.CommandProvider;

/** Adds {@code fdnet viewer} ({@code bench viewer} is fdnet-viewer/bench's). */
public final class ViewerCommandProvider implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new ViewerCommand());
    }
}

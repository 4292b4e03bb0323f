package org.fdnet.viewer.cli;

import java.util.List;
import org.fdnet.cli.CommandProvider;

/** Adds {@code fdnet viewer} and {@code fdnet bench viewer}. */
public final class ViewerCommandProvider implements CommandProvider {
    @Override
    public List<Object> commands() {
        return List.of(new ViewerCommand());
    }

    @Override
    public List<Object> benchmarks() {
        return List.of(new BenchViewerCommand());
    }
}

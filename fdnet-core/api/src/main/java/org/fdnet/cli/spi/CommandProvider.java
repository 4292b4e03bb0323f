package org.fdnet.cli.spi;

import java.util.List;

/**
 * How a part of FDNet adds commands to {@code fdnet} without the core knowing it: list an
 * implementation in {@code META-INF/services/org.fdnet.cli.spi.CommandProvider}. Each object is a picocli
 * {@code @Command}; its name is the subcommand's name.
 */
public interface CommandProvider {
    /**
     * Commands under {@code fdnet} (e.g. {@code run}, {@code logger}).
     *
     * @return picocli {@code @Command} objects, one per subcommand; none by default
     */
    default List<Object> commands() {
        return List.of();
    }

    /**
     * Benchmarks under {@code fdnet bench} (e.g. {@code core}, {@code logger}).
     *
     * @return picocli {@code @Command} objects, one per benchmark; none by default
     */
    default List<Object> benchmarks() {
        return List.of();
    }
}

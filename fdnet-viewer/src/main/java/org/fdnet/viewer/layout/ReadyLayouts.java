package org.fdnet.viewer.layout;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.Collection;
import java.util.List;
import java.util.Optional;
import org.fdnet.viewer.data.NodeSelection;

/**
 * The layouts the viewer ships, offered for a run whose Datas they name: a run holding every node of one of them
 * opens with it instead of with everything at once. RoQ's ({@code roq.layout}): attitude, sole forces, stability
 * margin, gait phase and the course track, each in its unit.
 */
public final class ReadyLayouts {
    private static final List<String> SHIPPED = List.of("roq.layout");

    private ReadyLayouts() {
    }

    /** The first shipped layout all of whose nodes are among {@code nodeNames} ({@code Module/Node}), if any. */
    public static Optional<ViewerLayout> forNodes(Collection<String> nodeNames) {
        for (String name : SHIPPED) {
            ViewerLayout layout = shipped(name);
            boolean all = layout.plots().stream().flatMap(p -> p.series().stream()).map(NodeSelection::node)
                    .allMatch(nodeNames::contains);
            if (all) {
                return Optional.of(layout);
            }
        }
        return Optional.empty();
    }

    /** A shipped layout by its resource name ({@code roq.layout}). */
    public static ViewerLayout shipped(String name) {
        try (InputStream in = ReadyLayouts.class.getResourceAsStream(name)) {
            if (in == null) {
                throw new IllegalStateException("the viewer's jar lacks its layout " + name);
            }
            return LayoutFile.parse(new String(in.readAllBytes(), StandardCharsets.UTF_8), name);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
    }
}

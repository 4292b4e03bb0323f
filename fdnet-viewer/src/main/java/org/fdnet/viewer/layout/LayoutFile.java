package org.fdnet.viewer.layout;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.viewer.data.NodeSelection;

/**
 * The viewer's layout file: plain text, a line per statement, {@code #} comments.
 *
 * <pre>
 *   window 20                      the shared time window, seconds
 *   legend beside                  or: legend hidden
 *   plot Sole forces               a plot, top to bottom, with its title
 *     main/foot forces[N]          a series: Module/Node, or one component Module/Node[2], then [unit]
 * </pre>
 *
 * A bad line fails naming the file, the line number and what was expected.
 */
public final class LayoutFile {
    private LayoutFile() {
    }

    public static ViewerLayout read(Path file) throws IOException {
        return parse(Files.readString(file, StandardCharsets.UTF_8), file.toString());
    }

    /** Parses layout text; {@code source} names it in messages. */
    public static ViewerLayout parse(String text, String source) {
        List<PlotSpec> plots = new ArrayList<>();
        String title = null;
        List<NodeSelection> series = new ArrayList<>();
        double window = 10;
        boolean legend = true;
        String[] lines = text.split("\r?\n", -1);
        for (int i = 0; i < lines.length; i++) {
            String line = lines[i].strip();
            String where = source + ":" + (i + 1) + ": ";
            if (line.isEmpty() || line.startsWith("#")) {
                continue;
            }
            if (line.startsWith("plot ") || line.equals("plot")) {
                if (title != null) {
                    plots.add(new PlotSpec(title, series));
                }
                title = line.substring(4).strip();
                series = new ArrayList<>();
            } else if (line.startsWith("window ")) {
                try {
                    window = Double.parseDouble(line.substring(7).strip());
                } catch (NumberFormatException e) {
                    throw new IllegalArgumentException(where + "'window' takes seconds, e.g. 'window 20', was '" + line + "'");
                }
                if (!(window > 0)) {
                    throw new IllegalArgumentException(where + "the time window must be longer than 0 s, was " + window);
                }
            } else if (line.startsWith("legend ")) {
                String how = line.substring(7).strip();
                if (!how.equals("beside") && !how.equals("hidden")) {
                    throw new IllegalArgumentException(where + "'legend' takes 'beside' or 'hidden', was '" + how + "'");
                }
                legend = how.equals("beside");
            } else if (title == null) {
                throw new IllegalArgumentException(where + "a series before any 'plot TITLE' line: '" + line + "'");
            } else {
                series.add(NodeSelection.parse(line));
            }
        }
        if (title != null) {
            plots.add(new PlotSpec(title, series));
        }
        if (plots.isEmpty()) {
            throw new IllegalArgumentException(source + ": no 'plot TITLE' line: a layout holds at least one plot");
        }
        return new ViewerLayout(plots, window, legend);
    }

    public static void write(ViewerLayout layout, Path file) throws IOException {
        Files.writeString(file, format(layout), StandardCharsets.UTF_8);
    }

    public static String format(ViewerLayout layout) {
        StringBuilder b = new StringBuilder("# FDNet viewer layout (fdnet viewer --layout FILE)\n");
        b.append("window ").append(layout.windowSeconds()).append('\n');
        b.append("legend ").append(layout.legendVisible() ? "beside" : "hidden").append('\n');
        for (PlotSpec p : layout.plots()) {
            b.append("plot ").append(p.title()).append('\n');
            p.series().forEach(s -> b.append("  ").append(s).append('\n'));
        }
        return b.toString();
    }
}

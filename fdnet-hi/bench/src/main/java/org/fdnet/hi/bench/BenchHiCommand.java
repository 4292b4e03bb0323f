package org.fdnet.hi.bench;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.concurrent.Callable;
import javax.swing.SwingUtilities;
import org.fdnet.bench.NetworkGenerator;
import org.fdnet.hi.app.OpenNetwork;
import org.fdnet.hi.graph.GraphCanvas;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.hi.layout.ElkLayeredLayout;
import org.fdnet.hi.layout.NodeSize;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code fdnet bench hi}: what the editor does when it opens a large network without .fdg — read and
 * validate the file, then lay it out with ELK — beside the bare ELK call on the same graph in the same
 * run; then the repaint of the whole graphic panel while nodes are dragged (each frame moves the
 * selection and paints the canvas, off-screen, as Swing would on screen).
 */
@Command(name = "hi", mixinStandardHelpOptions = true,
        description = {"Open + lay out a generated network (no .fdg) beside the bare ELK call; repaint while dragging.",
            "Targets for 1,000 nodes: open + lay out <= 2 s; repaint while dragging >= 30 frames/s."})
public final class BenchHiCommand implements Callable<Integer> {
    @Option(names = "--nodes", defaultValue = "1000", description = "nodes to generate (default ${DEFAULT-VALUE})")
    int nodes;

    @Option(names = "--connections", defaultValue = "2000", description = "connections to generate (default ${DEFAULT-VALUE})")
    int connections;

    @Option(names = "--modules", defaultValue = "10", description = "modules, main included (default ${DEFAULT-VALUE})")
    int modules;

    @Option(names = "--runs", defaultValue = "5", description = "timed repetitions after the first (default ${DEFAULT-VALUE})")
    int runs;

    @Option(names = "--frames", defaultValue = "200", description = "drag frames to paint (default ${DEFAULT-VALUE})")
    int frames;

    @Option(names = "--seed", defaultValue = "2004", description = "generator seed (default ${DEFAULT-VALUE})")
    long seed;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        if (nodes < 2 || connections < 1 || modules < 1 || runs < 1 || frames < 1) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    "--nodes must be at least 2; --connections, --modules, --runs and --frames at least 1");
        }
        Path dir = Files.createTempDirectory("fdnet-bench-hi");
        Path file = dir.resolve("generated.fdn");
        try {
            new NetworkGenerator(seed, false).writeTo(file, modules, nodes, connections, out);
            return measure(out, file);
        } finally {
            Files.deleteIfExists(file);
            Files.deleteIfExists(dir.resolve("generated.fdg"));
            Files.deleteIfExists(dir);
        }
    }

    private int measure(PrintWriter out, Path file) throws Exception {
        NetworkInfo network = NetworkRepository.load(file);
        double[] elk = new double[runs];
        double[] open = new double[runs];
        out.println("JIT: " + jitMode() + "; layout: " + layoutMode(network)
                + "; timing the first (cold) open + layout and the bare ELK call ...");
        out.flush();
        double openFirst = millis(() -> OpenNetwork.load(file));
        double elkFirst = millis(() -> ElkLayeredLayout.positions(network, r -> new NodeSize(120, 40)));
        for (int i = 0; i < runs; i++) {
            elk[i] = millis(() -> ElkLayeredLayout.positions(network, r -> new NodeSize(120, 40)));
            open[i] = millis(() -> OpenNetwork.load(file));
            out.printf("  run %d/%d: open + lay out %.0f ms, bare ELK %.0f ms%n", i + 1, runs, open[i], elk[i]);
            out.flush();
        }
        OpenNetwork opened = OpenNetwork.load(file);
        double fps = dragFramesPerSecond(opened, false);
        double fpsClose = dragFramesPerSecond(opened, true);
        out.println();
        out.printf("%-40s %10s %10s %10s%n", "", "first ms", "median ms", "best ms");
        row(out, "baseline: bare ELK layered call", elkFirst, elk);
        row(out, "open (read, validate) + lay out (ELK)", openFirst, open);
        out.printf("open + lay out = %.2f x bare ELK (median)%n", median(open) / median(elk));
        out.printf("repaint while dragging, whole network fitted (no names, no antialiasing): %.1f frames/s%n", fps);
        out.printf("repaint while dragging at zoom 1 (names, antialiasing): %.1f frames/s (1280x800 panel, %d frames each)%n",
                fpsClose, frames);
        out.printf("targets: open + lay out <= 2000 ms: %s (first %.0f ms, median %.0f ms); drag >= 30 frames/s: %s%n",
                verdict(Math.max(openFirst, median(open)) <= 2000), openFirst, median(open), verdict(Math.min(fps, fpsClose) >= 30));
        out.flush();
        return 0;
    }

    /** How the editor lays this network out (see ElkLayeredLayout). */
    private static String layoutMode(NetworkInfo network) {
        int nodes = ElkLayeredLayout.nodeCount(network);
        return ElkLayeredLayout.byModule(network)
                ? String.format("module by module (%,d nodes, at least %,d)", nodes, ElkLayeredLayout.BY_MODULE_FROM)
                : String.format("one graph (%,d nodes, under %,d)", nodes, ElkLayeredLayout.BY_MODULE_FROM);
    }

    /** Which compilers this JVM runs: the launcher stops the editor's at C1 (see bin/fdnet). */
    private static String jitMode() {
        return java.lang.management.ManagementFactory.getRuntimeMXBean().getInputArguments().stream()
                .filter(arg -> arg.startsWith("-XX:TieredStopAtLevel="))
                .reduce((first, last) -> last)
                .map(arg -> arg.endsWith("=1") ? "C1 only (" + arg + ")" : "tiered (" + arg + ")")
                .orElse("tiered C1 + C2 (the JVM's default)");
    }

    /** Selects 20 nodes and, frame after frame, moves them and paints the whole canvas. */
    private double dragFramesPerSecond(OpenNetwork opened, boolean zoomedIn) throws Exception {
        double[] fps = new double[1];
        SwingUtilities.invokeAndWait(() -> {
            GraphScene scene = opened.scene();
            GraphCanvas canvas = new GraphCanvas(scene);
            canvas.setSize(1280, 800);
            canvas.fit();
            List<NodeRef> all = new ArrayList<>(scene.visibleNodes());
            scene.select(new LinkedHashSet<>(all.subList(0, Math.min(20, all.size()))));
            if (zoomedIn) {
                canvas.setZoom(1);
                canvas.reveal(all.get(0));
            }
            BufferedImage image = new BufferedImage(1280, 800, BufferedImage.TYPE_INT_RGB);
            for (int i = 0; i < 20; i++) {
                paintFrame(canvas, scene, image, i);
            }
            long start = System.nanoTime();
            for (int i = 0; i < frames; i++) {
                paintFrame(canvas, scene, image, i);
            }
            fps[0] = frames / ((System.nanoTime() - start) / 1e9);
        });
        return fps[0];
    }

    private static void paintFrame(GraphCanvas canvas, GraphScene scene, BufferedImage image, int i) {
        scene.moveSelected(i % 2 == 0 ? 3 : -3, 1);
        Graphics2D g = image.createGraphics();
        try {
            canvas.paint(g);
        } finally {
            g.dispose();
        }
    }

    private interface Timed {
        Object run() throws Exception;
    }

    private static double millis(Timed t) throws Exception {
        long start = System.nanoTime();
        t.run();
        return (System.nanoTime() - start) / 1e6;
    }

    private static void row(PrintWriter out, String label, double first, double[] samples) {
        double[] sorted = samples.clone();
        Arrays.sort(sorted);
        out.printf("%-40s %10.1f %10.1f %10.1f%n", label, first, median(samples), sorted[0]);
    }

    private static double median(double[] samples) {
        double[] sorted = samples.clone();
        Arrays.sort(sorted);
        return sorted[sorted.length / 2];
    }

    private static String verdict(boolean met) {
        return met ? "met" : "MISSED";
    }
}

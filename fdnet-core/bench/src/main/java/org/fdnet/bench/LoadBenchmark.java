package org.fdnet.bench;

import java.io.InputStream;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.Callable;
import javax.xml.parsers.SAXParserFactory;
import org.fdnet.corba.QuickJitCommands;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.xml.sax.helpers.DefaultHandler;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code fdnet bench load}: loading and validating a large network, and the descendants query, each
 * beside a baseline measured in the same run: a bare non-validating SAX parse of the same file (what
 * reading the bytes costs at all), and a breadth-first search over plain int arrays of the same graph.
 *
 * <p>The cold figures come from fresh child JVMs that do nothing before the measured call
 * ({@link ColdLoadProbe}, what {@code fdnet validate} pays), with the whole {@code fdnet validate}
 * process timed beside {@code fdnet --version}; the warm medians come from this JVM. The targets are
 * judged on the cold figures and the warm medians, whichever is worse.
 */
@Command(name = "load", mixinStandardHelpOptions = true, subcommands = ColdLoadProbe.class,
        description = {"Load + validate a generated network and query descendants, beside same-run baselines.",
            "Cold: each of --cold-runs fresh child JVMs loads the file once (what fdnet validate pays).",
            "Warm: medians over --runs further loads in this JVM.",
            "Baselines: a bare SAX parse of the same file; a BFS over int arrays of the same graph.",
            "Targets for 10,000 nodes / 20,000 connections: load + validate <= 1 s, descendants <= 10 ms."})
public final class LoadBenchmark implements Callable<Integer> {
    @Option(names = "--nodes", defaultValue = "10000", description = "nodes to generate (default ${DEFAULT-VALUE})")
    int nodes;

    @Option(names = "--connections", defaultValue = "20000", description = "connections to generate (default ${DEFAULT-VALUE})")
    int connections;

    @Option(names = "--modules", defaultValue = "10", description = "modules, main included (default ${DEFAULT-VALUE})")
    int modules;

    @Option(names = "--runs", defaultValue = "10", description = "timed repetitions after the first (default ${DEFAULT-VALUE})")
    int runs;

    @Option(names = "--cold-runs", defaultValue = "3", description = "fresh child JVMs per cold figure (default ${DEFAULT-VALUE})")
    int coldRuns;

    @Option(names = "--seed", defaultValue = "2004", description = "generator seed (default ${DEFAULT-VALUE})")
    long seed;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        if (nodes < 2 || connections < 1 || modules < 1 || runs < 1 || coldRuns < 1) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    "--nodes must be at least 2, --connections, --modules, --runs and --cold-runs at least 1");
        }
        Path file = Files.createTempFile("fdnet-bench-load", ".fdn");
        try {
            NetworkInfo generated = new NetworkGenerator(seed, false).writeTo(file, modules, nodes, connections, out);
            ColdFigures cold = measureCold(out, file, busiestData(generated));
            return measure(out, file, cold);
        } finally {
            Files.deleteIfExists(file);
        }
    }

    /** Medians over fresh JVMs (n runs each): the probe's own timings and whole-process wall times. */
    private record ColdFigures(double[] bare, double[] load, double[] descendants, int reached, double[] version,
            double[] validate) {
    }

    /** Fresh child JVMs, one after another, while this JVM waits: nothing else of ours runs beside them. */
    private ColdFigures measureCold(PrintWriter out, Path file, NodeRef root) {
        double[] bare = new double[coldRuns];
        double[] load = new double[coldRuns];
        double[] descendants = new double[coldRuns];
        double[] version = new double[coldRuns];
        double[] validate = new double[coldRuns];
        int reached = -1;
        String path = file.toString();
        for (int i = 0; i < coldRuns; i++) {
            out.printf("cold run %d/%d: fresh JVMs for a bare parse, load + validate + descendants, fdnet --version,"
                    + " fdnet validate ...%n", i + 1, coldRuns);
            out.flush();
            bare[i] = probe("cold bare parse", List.of("bench", "load", "cold-probe", "--bare", path)).loadMillis();
            ColdLoadProbe.Figures f = probe("cold load", List.of("bench", "load", "cold-probe", "--root", root.toString(), path));
            load[i] = f.loadMillis();
            descendants[i] = f.descendantsMillis();
            reached = f.reached();
            version[i] = FreshJvmRun.of("fdnet --version", List.of("--version"), "").wallMillis();
            validate[i] = FreshJvmRun.of("fdnet validate", List.of("validate", path), ": valid").wallMillis();
        }
        return new ColdFigures(bare, load, descendants, reached, version, validate);
    }

    private static ColdLoadProbe.Figures probe(String label, List<String> args) {
        return ColdLoadProbe.Figures.parse(FreshJvmRun.of(label, args, ColdLoadProbe.MARKER).line(ColdLoadProbe.MARKER));
    }

    private int measure(PrintWriter out, Path file, ColdFigures cold) throws Exception {
        double saxFirst = millis(() -> bareParse(file));
        double loadFirst = millis(() -> NetworkRepository.load(file));
        double[] sax = new double[runs];
        double[] load = new double[runs];
        NetworkInfo network = null;
        for (int i = 0; i < runs; i++) {
            sax[i] = millis(() -> bareParse(file));
            long start = System.nanoTime();
            network = NetworkRepository.load(file);
            load[i] = (System.nanoTime() - start) / 1e6;
        }
        NodeRef root = busiestData(network);
        NetworkInfo queried = network;
        double descendantsFirst = millis(() -> queried.descendants(root));
        int reached = network.descendants(root).size();
        IntGraph graph = IntGraph.of(network);
        int rootIndex = graph.index(root);
        double[] descendants = new double[runs * 10];
        double[] bfs = new double[runs * 10];
        for (int i = 0; i < descendants.length; i++) {
            descendants[i] = millis(() -> queried.descendants(root));
            bfs[i] = millis(() -> graph.reach(rootIndex));
        }
        if (graph.reach(rootIndex) != reached) {
            throw new IllegalStateException("baseline BFS reached " + graph.reach(rootIndex) + " nodes, NetworkInfo " + reached);
        }
        if (cold.reached() != reached) {
            throw new IllegalStateException("the fresh JVM's descendants reached " + cold.reached() + " nodes, this JVM's " + reached);
        }
        double loadMedian = median(load);
        double descendantsMedian = median(descendants);
        double coldLoad = median(cold.load());
        double coldDescendants = median(cold.descendants());
        out.println();
        out.printf("cold: fresh JVM, nothing before the call (what fdnet validate pays), %d JVMs each; JIT %s,"
                + " as the launcher runs fdnet validate%n", coldRuns,
                QuickJitCommands.matches(List.of("validate")) ? "stopped at C1" : "tiered C1 + C2");
        out.printf("%-50s %10s %10s %10s%n", "", "median ms", "best ms", "worst ms");
        coldRow(out, "baseline: bare SAX parse, fresh JVM", cold.bare());
        coldRow(out, "load + validate, fresh JVM", cold.load());
        coldRow(out, "descendants (" + reached + "), first call in that JVM", cold.descendants());
        coldRow(out, "baseline: whole process fdnet --version", cold.version());
        coldRow(out, "whole process fdnet validate FILE", cold.validate());
        out.println();
        out.printf("warm: this JVM, after the generator, save and the cold runs; %d loads, %d queries%n", runs, runs * 10);
        out.printf("%-50s %10s %10s %10s%n", "", "first ms", "median ms", "best ms");
        row(out, "baseline: bare SAX parse (no DTD)", saxFirst, sax);
        row(out, "load + validate (DTD, rules, model)", loadFirst, load);
        row(out, "baseline: BFS over int arrays", Double.NaN, bfs);
        row(out, "descendants of " + root + " (" + reached + ")", descendantsFirst, descendants);
        out.println();
        out.printf("cold: load + validate = %.1f x a cold bare parse; fdnet validate = %.0f ms over fdnet --version%n",
                coldLoad / median(cold.bare()), median(cold.validate()) - median(cold.version()));
        out.printf("warm: load + validate = %.1f x bare parse; descendants = %.1f x bare BFS%n",
                loadMedian / median(sax), descendantsMedian / median(bfs));
        out.printf("targets: load + validate <= 1000 ms: %s (fresh JVM median %.0f ms, warm median %.0f ms);"
                        + " descendants <= 10 ms: %s (first call in a fresh JVM median %.2f ms, warm median %.2f ms)%n",
                verdict(Math.max(coldLoad, loadMedian) <= 1000), coldLoad, loadMedian,
                verdict(Math.max(coldDescendants, descendantsMedian) <= 10), coldDescendants, descendantsMedian);
        out.flush();
        return 0;
    }

    private static String verdict(boolean met) {
        return met ? "met" : "MISSED";
    }

    private static void coldRow(PrintWriter out, String label, double[] samples) {
        double[] sorted = samples.clone();
        Arrays.sort(sorted);
        out.printf("%-50s %10.2f %10.2f %10.2f%n", label, median(samples), sorted[0], sorted[sorted.length - 1]);
    }

    private static void row(PrintWriter out, String label, double first, double[] samples) {
        double[] sorted = samples.clone();
        Arrays.sort(sorted);
        out.printf("%-50s %10s %10.2f %10.2f%n", label, Double.isNaN(first) ? "-" : String.format("%.2f", first),
                median(samples), sorted[0]);
    }

    private static double median(double[] samples) {
        double[] sorted = samples.clone();
        Arrays.sort(sorted);
        return sorted[sorted.length / 2];
    }

    private interface Work {
        Object run() throws Exception;
    }

    private static double millis(Work work) throws Exception {
        long start = System.nanoTime();
        Object result = work.run();
        long elapsed = System.nanoTime() - start;
        if (result == null) {
            throw new IllegalStateException("benchmark work produced nothing");
        }
        return elapsed / 1e6;
    }

    /** A non-validating SAX parse that builds nothing; returns how many elements it saw. */
    static Object bareParse(Path file) throws Exception {
        SAXParserFactory factory = SAXParserFactory.newInstance();
        factory.setFeature("http://apache.org/xml/features/nonvalidating/load-external-dtd", false);
        int[] elements = new int[1];
        try (InputStream in = Files.newInputStream(file)) {
            factory.newSAXParser().parse(in, new DefaultHandler() {
                @Override
                public void startElement(String uri, String localName, String qName, org.xml.sax.Attributes attributes) {
                    elements[0]++;
                }
            });
        }
        return elements[0];
    }

    /**
     * The Data with the most connections of any kind (Readers and Writers): a root whose descendants are a
     * large part of the network.
     */
    private static NodeRef busiestData(NetworkInfo network) {
        NodeRef best = null;
        int most = -1;
        for (ModuleInfo m : network.modules()) {
            for (NodeInfo n : m.nodes()) {
                if (n.kind() == NodeKind.DATA) {
                    NodeRef ref = new NodeRef(m.name(), n.name());
                    int connected = network.connectionsOf(ref).size();
                    if (connected > most) {
                        most = connected;
                        best = ref;
                    }
                }
            }
        }
        return best;
    }

    /** The same graph as compressed int arrays: what a descendants query costs with nothing but the search. */
    private static final class IntGraph {
        private final Map<NodeRef, Integer> ids = new HashMap<>();
        private int[] offsets;
        private int[] targets;

        static IntGraph of(NetworkInfo network) {
            IntGraph g = new IntGraph();
            List<int[]> edges = new ArrayList<>();
            for (ModuleInfo m : network.modules()) {
                for (ConnectionInfo c : m.connections()) {
                    int data = g.id(c.data());
                    int relation = g.id(c.relation());
                    edges.add(c.kind() == ConnectionKind.READER ? new int[] {data, relation} : new int[] {relation, data});
                }
            }
            g.offsets = new int[g.ids.size() + 1];
            for (int[] e : edges) {
                g.offsets[e[0] + 1]++;
            }
            for (int i = 0; i < g.ids.size(); i++) {
                g.offsets[i + 1] += g.offsets[i];
            }
            g.targets = new int[edges.size()];
            int[] fill = Arrays.copyOf(g.offsets, g.offsets.length);
            for (int[] e : edges) {
                g.targets[fill[e[0]]++] = e[1];
            }
            return g;
        }

        private int id(NodeRef ref) {
            return ids.computeIfAbsent(ref, r -> ids.size());
        }

        int index(NodeRef ref) {
            return ids.get(ref);
        }

        int reach(int start) {
            boolean[] seen = new boolean[ids.size()];
            ArrayDeque<Integer> queue = new ArrayDeque<>();
            queue.add(start);
            int count = 0;
            while (!queue.isEmpty()) {
                int node = queue.poll();
                for (int i = offsets[node]; i < offsets[node + 1]; i++) {
                    int next = targets[i];
                    if (!seen[next]) {
                        seen[next] = true;
                        count++;
                        queue.add(next);
                    }
                }
            }
            return count;
        }
    }
}

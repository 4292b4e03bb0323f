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
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.ModuleCounts;
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
 */
@Command(name = "load", mixinStandardHelpOptions = true,
        description = {"Load + validate a generated network and query descendants, beside same-run baselines.",
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

    @Option(names = "--seed", defaultValue = "2004", description = "generator seed (default ${DEFAULT-VALUE})")
    long seed;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        PrintWriter out = spec.commandLine().getOut();
        if (nodes < 2 || connections < 1 || modules < 1 || runs < 1) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(),
                    "--nodes must be at least 2, --connections, --modules and --runs at least 1");
        }
        Path file = Files.createTempFile("fdnet-bench-load", ".fdn");
        try {
            out.printf("generating %,d nodes, %,d connections in %d modules (seed %d) ...%n", nodes, connections, modules, seed);
            out.flush();
            NetworkInfo generated = new NetworkGenerator(seed, false).generate(modules, nodes, connections);
            NetworkRepository.save(generated, file);
            ModuleCounts counts = generated.totalCounts();
            out.printf("file: %,d bytes; %,d Datas, %,d Relations, %,d Readers, %,d Writers%n", Files.size(file),
                    counts.datas(), counts.relations(), counts.readers(), counts.writers());
            out.flush();
            return measure(out, file);
        } finally {
            Files.deleteIfExists(file);
        }
    }

    private int measure(PrintWriter out, Path file) throws Exception {
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
        double loadMedian = median(load);
        double descendantsMedian = median(descendants);
        out.println();
        out.printf("%-38s %10s %10s %10s%n", "", "first ms", "median ms", "best ms");
        row(out, "baseline: bare SAX parse (no DTD)", saxFirst, sax);
        row(out, "load + validate (DTD, rules, model)", loadFirst, load);
        row(out, "baseline: BFS over int arrays", Double.NaN, bfs);
        row(out, "descendants of " + root + " (" + reached + ")", descendantsFirst, descendants);
        out.println();
        out.printf("load + validate = %.1f x bare parse; descendants = %.1f x bare BFS%n",
                loadMedian / median(sax), descendantsMedian / median(bfs));
        out.printf("targets: load + validate <= 1000 ms: %s (first %.0f ms, median %.0f ms); descendants <= 10 ms: %s (first %.2f ms, median %.2f ms)%n",
                verdict(Math.max(loadFirst, loadMedian) <= 1000), loadFirst, loadMedian,
                verdict(Math.max(descendantsFirst, descendantsMedian) <= 10), descendantsFirst, descendantsMedian);
        out.flush();
        return 0;
    }

    private static String verdict(boolean met) {
        return met ? "met" : "MISSED";
    }

    private static void row(PrintWriter out, String label, double first, double[] samples) {
        double[] sorted = samples.clone();
        Arrays.sort(sorted);
        out.printf("%-38s %10s %10.2f %10.2f%n", label, Double.isNaN(first) ? "-" : String.format("%.2f", first),
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

    private static Object bareParse(Path file) throws Exception {
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

    /** The Data with the most Readers: a root whose descendants are a large part of the network. */
    private static NodeRef busiestData(NetworkInfo network) {
        NodeRef best = null;
        int most = -1;
        for (ModuleInfo m : network.modules()) {
            for (NodeInfo n : m.nodes()) {
                if (n.kind() == NodeKind.DATA) {
                    NodeRef ref = new NodeRef(m.name(), n.name());
                    int readers = network.connectionsOf(ref).size();
                    if (readers > most) {
                        most = readers;
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

package org.fdnet.bench;

import java.util.ArrayList;
import java.util.Base64;
import java.util.List;
import java.util.Random;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;

/**
 * Builds random but valid networks from a seed: the load benchmark's 10,000-node network and the
 * property tests' many small ones. With {@code exotic} names and values use what a file must
 * escape or encode ({@code & < > "}, Japanese, leading blanks in values) and the file shapes a
 * loader must keep (inline declarations, {@code exist="no"}, connection names, shadowed names).
 */
public final class NetworkGenerator {
    private static final String[] EXOTIC_WORDS = {"姿勢", "バランス", "歩く", "a&b", "x<y", "say \"hi\"", "ümlaut", "plain"};

    private final long seed;
    private final Random random;
    private final boolean exotic;

    public NetworkGenerator(long seed, boolean exotic) {
        this.seed = seed;
        this.random = new Random(seed);
        this.exotic = exotic;
    }

    /** A network of about {@code nodes} nodes and exactly {@code connections} connections (fewer if the graph is too small). */
    /**
     * Generates a network and saves it to {@code file} (no {@code .fdg}), saying so on {@code out} with the file in
     * numbers: the one way the benchmarks make their input.
     */
    public NetworkInfo writeTo(java.nio.file.Path file, int modules, int nodes, int connections, java.io.PrintWriter out)
            throws java.io.IOException {
        out.printf("generating %,d nodes, %,d connections in %d modules (seed %d) ...%n", nodes, connections, modules, seed);
        out.flush();
        NetworkInfo generated = generate(modules, nodes, connections);
        org.fdnet.netinfo.xml.NetworkRepository.save(generated, file);
        org.fdnet.netinfo.ModuleCounts c = generated.totalCounts();
        out.printf("file: %,d bytes, no .fdg; %,d Datas, %,d Relations, %,d Readers, %,d Writers%n",
                java.nio.file.Files.size(file), c.datas(), c.relations(), c.readers(), c.writers());
        out.flush();
        return generated;
    }

    public NetworkInfo generate(int modules, int nodes, int connections) {
        NetworkInfo network = new NetworkInfo(exotic && random.nextBoolean() ? null : "generated-" + nodes);
        List<String> moduleNames = new ArrayList<>();
        moduleNames.add(ModuleInfo.MAIN);
        for (int m = 1; m < modules; m++) {
            String name = exotic ? word() + "-" + m : "Module" + m;
            network.addModule(name, random.nextBoolean());
            moduleNames.add(name);
        }
        List<NodeRef> datas = new ArrayList<>();
        List<NodeRef> relations = new ArrayList<>();
        for (int n = 0; n < nodes; n++) {
            String module = moduleNames.get(random.nextInt(moduleNames.size()));
            NodeKind kind = n % 2 == 0 ? NodeKind.DATA : NodeKind.RELATION;
            // A few names repeat across modules, so unqualified references must resolve own module first.
            String name = exotic && n > 4 && random.nextInt(8) == 0 ? "Node" + random.nextInt(n) : nodeName(n);
            if (network.module(module).hasNode(name)) {
                continue;
            }
            NodeInfo node = new NodeInfo(kind, name, random.nextInt(10) == 0 ? "robot" + random.nextInt(3) : "localhost",
                    random.nextInt(4) == 0 ? "nodes/lib" + random.nextInt(3) + ".jar" : "",
                    "org.example." + (kind == NodeKind.DATA ? "Sensor" : "Filter") + random.nextInt(20), parameters());
            (kind == NodeKind.DATA ? datas : relations).add(network.addNode(module, node));
        }
        if (datas.isEmpty() || relations.isEmpty()) {
            return network;
        }
        int attempts = 0;
        int made = 0;
        while (made < connections && attempts++ < connections * 4) {
            NodeRef data = datas.get(random.nextInt(datas.size()));
            NodeRef relation = relations.get(random.nextInt(relations.size()));
            ConnectionKind kind = random.nextBoolean() ? ConnectionKind.READER : ConnectionKind.WRITER;
            String declaring = random.nextInt(3) == 0 ? moduleNames.get(random.nextInt(moduleNames.size())) : relation.module();
            boolean inline = exotic && kind == ConnectionKind.READER && random.nextInt(4) == 0;
            ConnectionInfo c = new ConnectionInfo(kind, exotic && random.nextInt(5) == 0 ? "link" + made : null,
                    data, relation, !exotic || random.nextInt(10) != 0,
                    inline && data.module().equals(declaring), inline && relation.module().equals(declaring));
            if (network.connectionsOf(data).stream().anyMatch(l -> l.connection().sameLink(c))) {
                continue;
            }
            network.addConnection(declaring, c);
            made++;
        }
        return network;
    }

    private String nodeName(int n) {
        return exotic && random.nextInt(3) == 0 ? word() + n : "Node" + n;
    }

    private String word() {
        return EXOTIC_WORDS[random.nextInt(EXOTIC_WORDS.length)];
    }

    private List<Parameter> parameters() {
        List<Parameter> parameters = new ArrayList<>();
        int count = random.nextInt(exotic ? 4 : 2);
        for (int i = 0; i < count; i++) {
            String name = random.nextBoolean() ? "p" + i : null;
            ParameterType type = random.nextBoolean() ? null : ParameterType.values()[random.nextInt(ParameterType.values().length)];
            parameters.add(new Parameter(name, type, value(type)));
        }
        return parameters;
    }

    private String value(ParameterType type) {
        if (type == null || type == ParameterType.STRING) {
            return exotic ? " " + word() + "\t" + word() + " " : "v" + random.nextInt(100);
        }
        switch (type) {
            case BOOLEAN:
                return random.nextBoolean() ? "true" : "no";
            case LONG:
                return Long.toString(random.nextLong());
            case DOUBLE:
                return Double.toString(random.nextGaussian());
            case DOUBLES:
                return random.nextGaussian() + ", " + random.nextGaussian() + ", " + random.nextGaussian();
            case BYTES:
                byte[] bytes = new byte[random.nextInt(8)];
                random.nextBytes(bytes);
                return Base64.getEncoder().encodeToString(bytes);
            default:
                throw new AssertionError(type);
        }
    }
}

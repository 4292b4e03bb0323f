package org.fdnet.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Set;
import java.util.concurrent.Callable;
import org.fdnet.netinfo.ModuleCounts;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.ModuleTree;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.netinfo.xml.Problem;
import org.fdnet.runtime.loading.ClassLoadingPolicy;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code fdnet info FILE}: the network in numbers, per module (the thesis's "FDNetworks in numbers"); with
 * {@code --params}, every node's declared parameters ({@link ParameterListing}).
 */
@Command(name = "info", mixinStandardHelpOptions = true,
        description = {"Show a network in numbers: modules, Datas, Relations, Readers and Writers per module.",
                "With --params, also every node's declared parameters: the value the file gives, the default, what is"
                        + " allowed, whether it may change while the network runs, and what it does."})
public final class InfoCommand implements Callable<Integer> {
    @Parameters(paramLabel = "FILE", description = "the .fdn network definition")
    Path file;

    @Option(names = "--params", description = "list every node's declared parameters with their descriptions")
    boolean params;

    @Option(names = "--allow-path", paramLabel = "DIR",
            description = "another folder node classes may be loaded from (besides the file's folder), as for run")
    List<Path> allowedRoots = new ArrayList<>();

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        NetworkInfo network;
        try {
            network = NetworkRepository.load(file);
        } catch (NetworkFileException e) {
            e.problems().stream().map(Problem::toString).forEach(out::println);
            out.flush();
            return 1;
        }
        out.printf("network %s (%s), %d modules%n", network.name() == null ? "(unnamed)" : network.name(), file,
                network.modules().size());
        String row = "%-20s %-6s %7s %10s %8s %8s%n";
        out.printf(row, "module", "load", "Datas", "Relations", "Readers", "Writers");
        Set<String> atStart = ModuleTree.atStart(network);
        for (ModuleInfo m : network.modules()) {
            ModuleCounts c = m.counts();
            out.printf(row, m.name(), loadColumn(m, atStart), c.datas(), c.relations(), c.readers(), c.writers());
        }
        ModuleCounts t = network.totalCounts();
        out.printf(row, "total", "", t.datas(), t.relations(), t.readers(), t.writers());
        int unresolved = params
                ? new ParameterListing(out).list(network, ClassLoadingPolicy.forNetworkFile(file, allowedRoots)) : 0;
        out.flush();
        return unresolved == 0 ? 0 : 1;
    }

    /** start: loaded at start; parent: a nested module loaded with its parent, which is not; later: on request. */
    private static String loadColumn(ModuleInfo m, Set<String> atStart) {
        if (atStart.contains(m.name())) {
            return "start";
        }
        return m.loadAtStart() ? "parent" : "later";
    }
}

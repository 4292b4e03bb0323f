package org.fdnet.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code fdnet bench load cold-probe FILE}: what {@code bench load} runs in a fresh child JVM. It does
 * nothing before its one measured call, so the call pays what {@code fdnet validate} pays: class loading,
 * the JAXB context, the DTD, the model's rules, an interpreter not yet warmed by the JIT. With
 * {@code --root} it then times the descendants query's first call in that JVM; with {@code --bare} it
 * times a bare SAX parse instead (the cold baseline). Prints one line starting with {@value #MARKER}.
 */
@Command(name = "cold-probe", hidden = true, mixinStandardHelpOptions = true,
        description = "Loads + validates FILE once in this (fresh) JVM and prints its own timing; used by bench load.")
public final class ColdLoadProbe implements Callable<Integer> {
    static final String MARKER = "cold-probe:";

    @Parameters(index = "0", paramLabel = "FILE", description = "the .fdn file to load")
    Path file;

    @Option(names = "--root", paramLabel = "MODULE/NODE", description = "also time the first descendants query from this node")
    String root;

    @Option(names = "--bare", description = "time a bare non-validating SAX parse instead of the load (the baseline)")
    boolean bare;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws Exception {
        if (!Files.isRegularFile(file)) {
            spec.commandLine().getErr().println(file + ": no such file");
            return 1;
        }
        long start = System.nanoTime();
        Object loaded;
        try {
            loaded = bare ? LoadBenchmark.bareParse(file) : NetworkRepository.load(file);
        } catch (NetworkFileException e) {
            spec.commandLine().getErr().println(e.getMessage());
            return 1;
        }
        double loadMillis = (System.nanoTime() - start) / 1e6;
        double descendantsMillis = Double.NaN;
        int reached = -1;
        if (root != null && loaded instanceof NetworkInfo network) {
            NodeRef ref = NodeRef.parse(root, "main");
            long q0 = System.nanoTime();
            reached = network.descendants(ref).size();
            descendantsMillis = (System.nanoTime() - q0) / 1e6;
        }
        long uptime = java.lang.management.ManagementFactory.getRuntimeMXBean().getUptime();
        spec.commandLine().getOut().println(String.format(Locale.ROOT,
                "%s load-ms=%.3f descendants-ms=%.3f reached=%d jvm-uptime-ms=%d", MARKER, loadMillis,
                descendantsMillis, reached, uptime));
        spec.commandLine().getOut().flush();
        return 0;
    }

    /** The probe's figures, read back from its line. */
    record Figures(double loadMillis, double descendantsMillis, int reached, double uptimeMillis) {
        static Figures parse(String line) {
            String[] parts = line.substring(line.indexOf(MARKER) + MARKER.length()).trim().split("\\s+");
            return new Figures(value(parts[0]), value(parts[1]), (int) value(parts[2]), value(parts[3]));
        }

        private static double value(String keyValue) {
            return Double.parseDouble(keyValue.substring(keyValue.indexOf('=') + 1));
        }
    }
}

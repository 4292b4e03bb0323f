package org.fdnet.cli;

import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.Callable;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.netinfo.ModuleCounts;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.xml.LayoutRepository;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.netinfo.xml.Problem;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code fdnet validate FILE...}: checks .fdn and .fdg files; exit 0 when all are valid. */
@Command(name = "validate", mixinStandardHelpOptions = true,
        description = {"Check network definitions (.fdn) and graphic side files (.fdg) against the FDNet DTDs and rules.",
            "Prints one line per problem, FILE:LINE:COL: message, and exits 1 if any file is invalid."},
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = {"0:every file is valid", "1:at least one file has a problem"})
public final class ValidateCommand implements Callable<Integer> {
    @Parameters(arity = "1..*", paramLabel = "FILE", description = "the .fdn or .fdg files to check")
    List<Path> files;

    @Option(names = {"-q", "--quiet"}, description = "print only problems, not a line per valid file")
    boolean quiet;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        boolean allValid = true;
        for (Path file : files) {
            try {
                String summary = isLayout(file) ? checkLayout(file, out) : checkNetwork(file);
                if (!quiet) {
                    out.println(file + ": valid (" + summary + ")");
                }
            } catch (NetworkFileException e) {
                allValid = false;
                for (Problem p : e.problems()) {
                    out.println(p);
                }
            }
        }
        out.flush();
        return allValid ? 0 : 1;
    }

    private static boolean isLayout(Path file) {
        return file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".fdg");
    }

    private static String checkNetwork(Path file) throws NetworkFileException {
        NetworkInfo network = NetworkRepository.load(file);
        ModuleCounts total = network.totalCounts();
        return network.modules().size() + " modules, " + total.datas() + " Datas, " + total.relations()
                + " Relations, " + total.readers() + " Readers, " + total.writers() + " Writers";
    }

    /** A layout is checked alone; when its network sits beside it, names it no longer has are warnings. */
    private static String checkLayout(Path file, PrintWriter out) throws NetworkFileException {
        NetworkLayout layout = LayoutRepository.load(file);
        String name = file.getFileName().toString();
        Path definition = file.resolveSibling(name.substring(0, name.length() - 4) + ".fdn");
        int nodes = layout.modules().stream().mapToInt(m -> m.nodes().size()).sum();
        if (Files.isRegularFile(definition)) {
            try {
                for (String stale : layout.staleEntries(NetworkRepository.load(definition))) {
                    out.println(file + ": warning: " + stale + " is not in " + definition.getFileName());
                }
            } catch (NetworkFileException e) {
                out.println(file + ": warning: cannot compare with " + definition + ", which is invalid");
            }
        }
        return layout.modules().size() + " modules, " + nodes + " node layouts";
    }
}

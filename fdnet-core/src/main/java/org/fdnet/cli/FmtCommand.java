package org.fdnet.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.Callable;
import org.fdnet.netinfo.xml.NetworkDocument;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.netinfo.xml.Problem;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/** {@code fdnet fmt FILE...}: rewrites network definitions in canonical form. */
@Command(name = "fmt", mixinStandardHelpOptions = true,
        description = {"Rewrite .fdn files in canonical form: UTF-8, a DOCTYPE, stable order, four-space indentation.",
            "Invalid files are reported and left untouched."},
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = {"0:all files are (now) canonical", "1:a file is invalid, or with --check not canonical"})
public final class FmtCommand implements Callable<Integer> {
    @Parameters(arity = "1..*", paramLabel = "FILE", description = "the .fdn files to rewrite")
    List<Path> files;

    @Option(names = "--check", description = "change nothing; exit 1 and name the files that are not canonical")
    boolean check;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        PrintWriter out = spec.commandLine().getOut();
        int status = 0;
        for (Path file : files) {
            NetworkDocument document;
            try {
                document = NetworkRepository.read(file);
            } catch (NetworkFileException e) {
                e.problems().stream().map(Problem::toString).forEach(out::println);
                status = 1;
                continue;
            }
            String systemId = document.doctypeSystemId() == null ? NetworkRepository.DEFAULT_SYSTEM_ID : document.doctypeSystemId();
            byte[] canonical = NetworkRepository.toBytes(document.network(), systemId, document.leadingComments());
            boolean same = Arrays.equals(canonical, Files.readAllBytes(file));
            if (same) {
                continue;
            }
            if (check) {
                out.println(file + ": not in canonical form");
                status = 1;
            } else {
                NetworkRepository.save(document.network(), file, systemId, document.leadingComments());
                out.println(file + ": rewritten" + (document.innerComments() == 0 ? ""
                        : " (" + document.innerComments() + " comments inside <cnet> were not kept: move notes to the header comment)"));
            }
        }
        out.flush();
        return status;
    }
}

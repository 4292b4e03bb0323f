package org.fdnet.cli;

import java.io.IOException;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code fdnet reference}: prints the command-line reference, or with {@code --write} rewrites
 * {@code docs/reference/cli.md} and the README's command table in the project. Hidden: it documents the others.
 */
@Command(name = "reference", hidden = true, mixinStandardHelpOptions = true,
        description = "Print the command-line reference (Markdown), or rewrite docs/reference/cli.md and README.md's table.")
public final class ReferenceCommand implements Callable<Integer> {
    @Option(names = "--write", description = "rewrite the files under --root instead of printing")
    boolean write;

    @Option(names = "--root", description = "the project's root (default: the launcher's, else the current directory)")
    Path root;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws IOException {
        CliReference reference = new CliReference(spec.root().commandLine());
        PrintWriter out = spec.commandLine().getOut();
        if (!write) {
            out.print(reference.page());
            out.flush();
            return 0;
        }
        Path project = root != null ? root : Path.of(System.getProperty("fdnet.home", "."));
        Path page = project.resolve(CliReference.PAGE);
        Path readme = project.resolve("README.md");
        Files.createDirectories(page.getParent());
        Files.writeString(page, reference.page(), StandardCharsets.UTF_8);
        Files.writeString(readme, reference.withReadmeTable(Files.readString(readme, StandardCharsets.UTF_8)),
                StandardCharsets.UTF_8);
        out.println("wrote " + page + " and the command table of " + readme);
        out.flush();
        return 0;
    }
}

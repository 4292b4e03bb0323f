package org.fdnet.cli;

import java.io.PrintWriter;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.function.Consumer;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code fdnet sdk install}: builds this checkout and installs its artifacts into the local Maven repository
 * ({@code mvn -B -DskipTests install}), offline first and online only when an artifact is missing.
 */
@Command(name = "install", mixinStandardHelpOptions = true,
        description = {"Build this FDNet checkout and install its artifacts into your local Maven repository, so "
                + "that a Maven project can depend on them: the node API, the runtime, roq-sim with its native "
                + "library built for this machine, the test kits, the archetype and the BOM org.fdnet:fdnet-bom.",
            "Runs mvn -B -DskipTests install in the checkout, offline first (-o), then online when an artifact is "
                + "not in the local repository yet. Prints a line per module installed, then the lines to paste "
                + "into your pom.xml."},
        exitCodeListHeading = "Exit codes:%n",
        exitCodeList = {"0:installed", "1:the build failed (its last lines and the log are printed)"})
public final class SdkInstallCommand implements Callable<Integer> {
    @Option(names = "--online", description = "build online from the start (default: offline first)")
    boolean online;

    @Option(names = "--tests", description = "run the tests too (about 11 minutes; default: -DskipTests)")
    boolean tests;

    @Parameters(paramLabel = "MAVEN_ARG", arity = "0..*",
            description = "more arguments for Maven, after --: e.g. -- -Dmaven.repo.local=/srv/m2")
    List<String> mavenArguments = new ArrayList<>();

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        FdnetSdk sdk;
        try {
            sdk = FdnetSdk.current();
        } catch (IllegalStateException e) {
            err.println("fdnet sdk install: " + e.getMessage());
            return 1;
        }
        Path log = sdk.root().resolve("target").resolve("fdnet-sdk-install.log");
        long start = System.nanoTime();
        out.println("installing FDNet " + sdk.version() + " from " + sdk.root() + " (log: " + log + ")");
        out.flush();
        Consumer<InstallProgress.Installed> printer = module -> {
            out.println(module.position() + " " + module.artifactId() + ": " + String.join(", ", module.kinds()));
            out.flush();
        };
        InstallProgress progress = new InstallProgress(printer);
        MavenRun run;
        try {
            run = MavenRun.run(sdk.root(), arguments(!online), log, progress);
            if (run.missedAnArtifactOffline()) {
                out.println("an artifact is not in the local Maven repository yet: building online");
                out.flush();
                progress = new InstallProgress(printer);
                run = MavenRun.run(sdk.root(), arguments(false), log, progress);
            }
        } catch (IllegalStateException e) {
            err.println("fdnet sdk install: " + e.getMessage());
            return 1;
        }
        progress.finishModule();
        if (!run.succeeded()) {
            err.println("fdnet sdk install: Maven failed (exit " + run.exitCode() + "); its last lines:");
            run.lastLines().forEach(err::println);
            err.println("the whole output: " + log);
            return 1;
        }
        printSummary(out, sdk, progress, (System.nanoTime() - start) / 1_000_000_000L);
        return 0;
    }

    private List<String> arguments(boolean offline) {
        List<String> arguments = new ArrayList<>(List.of("-B"));
        if (offline) {
            arguments.add("-o");
        }
        if (!tests) {
            arguments.add("-DskipTests");
        }
        arguments.add("install");
        arguments.addAll(mavenArguments);
        return arguments;
    }

    private static void printSummary(PrintWriter out, FdnetSdk sdk, InstallProgress progress, long seconds) {
        int files = progress.installed().stream().mapToInt(m -> m.files().size()).sum();
        out.printf("installed %d artifacts (%d files) into %s in %d min %02d s%n", progress.installed().size(), files,
                progress.commonFolder(), seconds / 60, seconds % 60);
        out.println("name FDNet's artifacts without versions: import the BOM in your pom.xml");
        out.println(sdk.bomImport().indent(2).stripTrailing());
        out.println("or start a project that does: " + sdk.root().resolve("bin/fdnet") + " new nodes DIR");
        out.flush();
    }
}

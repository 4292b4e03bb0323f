package org.fdnet.cli;

import org.fdnet.cli.spi.CommandProvider;
import java.util.ServiceLoader;
import org.fdnet.logging.QuietTerminalLogging;
import picocli.CommandLine;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Spec;

/**
 * The {@code fdnet} command: the entry point of {@code bin/fdnet}. The core's own commands are listed
 * here; the other parts add theirs through {@link CommandProvider}.
 */
@Command(name = "fdnet", mixinStandardHelpOptions = true, version = "FDNet 0.1.0",
        description = "Flat Distributed Network: define, check, run and observe FDNetworks.",
        subcommands = {ValidateCommand.class, InfoCommand.class, FmtCommand.class, KeysCommand.class, SdkCommand.class,
            NewCommand.class})
public final class FdnetCommand implements Runnable {
    @Spec
    CommandSpec spec;

    @Override
    public void run() {
        spec.commandLine().usage(spec.commandLine().getOut());
    }

    /** The full command tree, with every provider's commands and benchmarks. */
    public static CommandLine commandLine() {
        CommandLine root = new CommandLine(new FdnetCommand());
        CommandLine bench = new CommandLine(new BenchCommand());
        for (CommandProvider provider : ServiceLoader.load(CommandProvider.class)) {
            provider.commands().forEach(root::addSubcommand);
            provider.benchmarks().forEach(bench::addSubcommand);
        }
        root.addSubcommand("bench", bench);
        return root;
    }

    public static void main(String[] args) {
        QuietTerminalLogging.select(); // before any logger: third-party INFO to a log file, warnings to the terminal
        System.exit(commandLine().execute(args));
    }
}

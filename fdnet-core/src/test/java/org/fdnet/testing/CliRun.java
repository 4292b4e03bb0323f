package org.fdnet.testing;

import java.io.PrintWriter;
import java.io.StringWriter;
import org.fdnet.cli.FdnetCommand;
import picocli.CommandLine;

/** Runs {@code fdnet} commands in-process, as bin/fdnet would, and keeps what they print. */
public final class CliRun {
    private final StringWriter output = new StringWriter();

    /** Runs one command line; returns its exit code. Output and errors accumulate in {@link #output()}. */
    public int fdnet(String... args) {
        CommandLine cli = FdnetCommand.commandLine();
        cli.setOut(new PrintWriter(output, true));
        cli.setErr(new PrintWriter(output, true));
        return cli.execute(args);
    }

    public String output() {
        return output.toString();
    }

    public void clear() {
        output.getBuffer().setLength(0);
    }
}

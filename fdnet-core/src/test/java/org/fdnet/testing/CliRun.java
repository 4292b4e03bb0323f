package org.fdnet.testing;

import java.io.ByteArrayInputStream;
import java.io.InputStream;
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
        // fdnet run reads commands on standard input; in-process it gets none, so it never reads the test
        // JVM's own standard input (surefire's command channel to its forked JVM).
        InputStream stdin = System.in;
        System.setIn(new ByteArrayInputStream(new byte[0]));
        try {
            return cli.execute(args);
        } finally {
            System.setIn(stdin);
        }
    }

    public String output() {
        return output.toString();
    }

    public void clear() {
        output.getBuffer().setLength(0);
    }
}

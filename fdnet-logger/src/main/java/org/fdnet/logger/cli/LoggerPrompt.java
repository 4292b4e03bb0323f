package org.fdnet.logger.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.PrintStream;
import java.util.Locale;
import org.fdnet.logger.LoggerStatus;
import org.fdnet.logger.NetworkStateLogger;

/**
 * The headless logger's prompt: one command a line on standard input. {@code retry} tells a writer that
 * reported the database DOWN to try again (what the panel's <em>Retry database</em> button and SIGHUP do),
 * {@code status} prints the status line, {@code help} lists the commands. An unknown line is answered with
 * the list, never fatal; the end of input ends the prompt, not the logger.
 */
public final class LoggerPrompt implements Runnable {
    static final String HELP = "commands: retry (try a database reported DOWN again), status, help";

    private final NetworkStateLogger logger;
    private final BufferedReader in;
    private final PrintStream out;

    public LoggerPrompt(NetworkStateLogger logger, BufferedReader in, PrintStream out) {
        this.logger = logger;
        this.in = in;
        this.out = out;
    }

    @Override
    public void run() {
        try {
            for (String line = in.readLine(); line != null; line = in.readLine()) {
                answer(line.trim().toLowerCase(Locale.ROOT));
            }
        } catch (IOException e) {
            out.println("fdnet logger: no commands from standard input (" + e.getMessage() + "); kill -HUP retries the"
                    + " database instead; the logger runs on");
        }
    }

    /** Carries out one command line. */
    void answer(String command) {
        switch (command) {
            case "" -> { }
            case "retry" -> {
                out.println("fdnet logger: retrying the database (was: " + logger.writer().databaseState() + ")");
                logger.retryDatabase();
            }
            case "status" -> {
                LoggerStatus s = logger.status();
                out.println(s.running() ? s.line() : "fdnet logger: not running");
            }
            case "help" -> out.println(HELP);
            default -> out.println("fdnet logger: unknown command '" + command + "'; " + HELP);
        }
        out.flush();
    }
}

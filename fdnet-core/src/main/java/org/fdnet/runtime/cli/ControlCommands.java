package org.fdnet.runtime.cli;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.nio.charset.StandardCharsets;
import java.util.Set;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.NetworkControl;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The commands {@code fdnet run} takes on standard input while a network runs, one a line, each answered by one
 * line ({@code ok: …}, {@code refused: …} or {@code error: …}). They act through {@link NetworkControl}, so a
 * single-host run and a distributed run take the same commands.
 *
 * <pre>
 *   stdin line ─ parse ─▶ NetworkControl (Controller | DistributedControl) ─▶ ChangeOutcome ─▶ answer line
 * </pre>
 */
public final class ControlCommands {
    private static final Logger LOG = LoggerFactory.getLogger(ControlCommands.class);

    static final String HELP = String.join(System.lineSeparator(),
            "commands (one a line):",
            "  load MODULE                   load a module",
            "  unload MODULE                 unload a module",
            "  hold MODULE                   put a module's Relations on hold",
            "  resume MODULE                 let a held module's Relations fire again",
            "  set [MODULE/]NODE/PARAM=VALUE set a node parameter (a bare NODE is in main)",
            "  send [MODULE/]NODE=VALUE      write a value into a Data",
            "  help                          this list");

    private static final Set<String> VERBS = Set.of("load", "unload", "hold", "resume", "set", "send");

    private final NetworkControl control;
    private final PrintWriter out;

    public ControlCommands(NetworkControl control, PrintWriter out) {
        this.control = control;
        this.out = out;
    }

    /** Reads commands from {@code in} on a daemon thread until it ends; the run goes on meanwhile. */
    public Thread readFrom(InputStream in) {
        Thread t = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8))) {
                String line;
                while ((line = r.readLine()) != null) {
                    String answer = execute(line);
                    if (answer != null) {
                        synchronized (out) {
                            out.println(answer);
                            out.flush();
                        }
                    }
                }
            } catch (IOException e) {
                LOG.warn("standard input closed: {}; no more commands", e.getMessage());
            }
        }, "fdnet-run-commands");
        t.setDaemon(true);
        t.start();
        return t;
    }

    /** Executes one command line; returns the answer, or {@code null} for a blank line. */
    public String execute(String line) {
        String text = line.strip();
        if (text.isEmpty()) {
            return null;
        }
        int space = text.indexOf(' ');
        String verb = space < 0 ? text : text.substring(0, space);
        String arg = space < 0 ? "" : text.substring(space + 1).strip();
        if (verb.equals("help")) {
            return HELP;
        }
        if (!VERBS.contains(verb)) {
            return "error: unknown command '" + verb + "' (type help)";
        }
        if (arg.isEmpty()) {
            return "error: " + verb + " needs an argument (type help)";
        }
        try {
            ChangeOutcome o = switch (verb) {
                case "load" -> control.load(arg);
                case "unload" -> control.unload(arg);
                case "hold" -> control.hold(arg);
                case "resume" -> control.resume(arg);
                case "set" -> setParameter(arg);
                case "send" -> {
                    ValueAssignment a = ValueAssignment.parse(arg);
                    yield control.send(a.data(), a.value());
                }
                default -> throw new IllegalStateException("verb " + verb + " listed but not handled");
            };
            return o.executed() ? "ok: " + o.description() : "refused: " + o.description() + ": " + o.reason();
        } catch (IllegalArgumentException e) {
            return "error: " + text + ": " + e.getMessage();
        }
    }

    /** {@code [MODULE/]NODE/PARAM=VALUE}: the last '/' before '=' separates the parameter. */
    private ChangeOutcome setParameter(String arg) {
        int eq = arg.indexOf('=');
        int slash = eq < 0 ? -1 : arg.lastIndexOf('/', eq);
        if (eq < 0 || slash <= 0) {
            throw new IllegalArgumentException("expected [MODULE/]NODE/PARAM=VALUE");
        }
        NodeRef node = NodeRef.parse(arg.substring(0, slash).strip(), ModuleInfo.MAIN);
        return control.setParameter(node, arg.substring(slash + 1, eq).strip(), arg.substring(eq + 1));
    }
}

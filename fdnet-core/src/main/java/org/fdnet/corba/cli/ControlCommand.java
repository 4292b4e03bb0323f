package org.fdnet.corba.cli;

import java.io.PrintWriter;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.StringJoiner;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicLong;
import org.fdnet.control.LiveNetworkListener;
import org.fdnet.control.NetworkUnreachableException;
import org.fdnet.corba.OrbSettings;
import org.fdnet.corba.control.RemoteLiveNetwork;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.cli.ControlCommands;
import org.fdnet.runtime.cli.DurationText;
import org.fdnet.tls.TlsOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;
import picocli.CommandLine.Model.CommandSpec;

/**
 * {@code fdnet control NAME VERB [ARG]}: acts on a running network through its control object, from a terminal or a
 * script. The changes are the ones {@code fdnet run} takes on its standard input ({@link ControlCommands}), answered
 * by the same {@code ok: …} / {@code refused: …: reason} line; {@code status} and {@code watch} look at it.
 * Exit 0 when it was executed, 1 when it was refused or the network cannot be reached, 2 for bad usage.
 */
@Command(name = "control", mixinStandardHelpOptions = true,
        description = {"Act on a running network (fdnet run, fdnet demo) through its control object.",
                "NAME is the network's name (a run on this machine, or one in the naming service with --naming),"
                        + " HOST:PORT (a run's --control-port) or a corbaloc.",
                "Verbs: status | load MODULE | unload MODULE | hold MODULE | resume MODULE"
                        + " | set MODULE/NODE:PARAM=VALUE | send MODULE/NODE=VALUE | watch [--for 10s]"})
public final class ControlCommand implements Callable<Integer> {
    @Parameters(index = "0", paramLabel = "NAME", description = "the network: its name, HOST:PORT or a corbaloc")
    String target;

    @Parameters(index = "1", paramLabel = "VERB", description = "status, load, unload, hold, resume, set, send, watch")
    String verb;

    @Parameters(index = "2..*", paramLabel = "ARG", description = "the module, MODULE/NODE:PARAM=VALUE or MODULE/NODE=VALUE")
    List<String> args = new ArrayList<>();

    @Option(names = "--naming", paramLabel = "CORBALOC",
            description = "look NAME up in this naming service (a distributed run registers there)")
    String naming;

    @Option(names = "--naming-port", paramLabel = "PORT", description = "a naming service on 127.0.0.1 at PORT")
    Integer namingPort;

    @Option(names = "--for", paramLabel = "DURATION", converter = DurationText.class,
            description = "watch: how long (default: until the network stops or Ctrl-C)")
    Duration duration;

    @Mixin
    TlsOptions tls;

    @Spec
    CommandSpec spec;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        try {
            tls.apply();
        } catch (IllegalArgumentException e) {
            err.println("fdnet control: " + e.getMessage());
            err.flush();
            return 2;
        }
        String namingRef = naming != null ? naming
                : namingPort != null ? OrbSettings.namingCorbaloc(OrbSettings.LOOPBACK, namingPort) : null;
        RemoteLiveNetwork network;
        try {
            network = RemoteLiveNetwork.attach(target, namingRef);
        } catch (NetworkUnreachableException e) {
            err.println(e.getMessage());
            err.flush();
            return 1;
        }
        try {
            return switch (verb) {
                case "status" -> status(network, out);
                case "watch" -> watch(network, out);
                default -> change(network, out);
            };
        } catch (NetworkUnreachableException e) {
            err.println(e.getMessage());
            err.flush();
            return 1;
        } finally {
            network.close();
        }
    }

    private int status(RemoteLiveNetwork network, PrintWriter out) {
        NetworkInfo snapshot = network.snapshot();
        out.printf("network %s at %s%n", network.name(), network.address());
        out.printf("  modules loaded: %s; on hold: %s%n", network.loadedModules(),
                network.heldModules().isEmpty() ? "none" : network.heldModules());
        for (ModuleInfo m : snapshot.modules()) {
            var c = m.counts();
            out.printf("  %-24s %d Datas, %d Relations, %d Readers, %d Writers%n", m.name(), c.datas(), c.relations(),
                    c.readers(), c.writers());
        }
        out.flush();
        return 0;
    }

    private int change(RemoteLiveNetwork network, PrintWriter out) {
        String line = verb + (args.isEmpty() ? "" : " " + String.join(" ", args));
        if (verb.equals("set")) {
            line = "set " + parameterAssignment(String.join(" ", args));
        }
        String answer = new ControlCommands(network, out).execute(line);
        out.println(answer);
        out.flush();
        if (answer.startsWith("ok:")) {
            return 0;
        }
        return answer.startsWith("refused:") ? 1 : 2;
    }

    /** {@code MODULE/NODE:PARAM=VALUE} as {@link ControlCommands} takes it, {@code MODULE/NODE/PARAM=VALUE}. */
    static String parameterAssignment(String arg) {
        int eq = arg.indexOf('=');
        int colon = eq < 0 ? arg.lastIndexOf(':') : arg.lastIndexOf(':', eq);
        return colon < 0 ? arg : arg.substring(0, colon) + "/" + arg.substring(colon + 1);
    }

    private int watch(RemoteLiveNetwork network, PrintWriter out) throws InterruptedException {
        CountDownLatch ended = new CountDownLatch(1);
        AtomicLong changes = new AtomicLong();
        AtomicLong samples = new AtomicLong();
        long started = System.nanoTime();
        out.printf("watching %s at %s%n", network.name(), network.address());
        out.flush();
        LiveNetworkListener printer = new LiveNetworkListener() {
            @Override
            public void changeSettled(ChangeOutcome outcome) {
                changes.incrementAndGet();
                say(out, started, "change " + outcome);
            }

            @Override
            public void valuesSampled(Map<NodeRef, Value> latest) {
                samples.incrementAndGet();
                StringJoiner j = new StringJoiner("  ");
                latest.forEach((ref, v) -> j.add(ref + "=" + shortText(v)));
                say(out, started, "values " + j);
            }

            @Override
            public void disconnected(String reason) {
                say(out, started, "disconnected: " + reason);
                ended.countDown();
            }
        };
        Thread hook = new Thread(ended::countDown, "fdnet-control-stop");
        Runtime.getRuntime().addShutdownHook(hook);
        try (AutoCloseable subscription = network.subscribe(printer)) {
            if (duration == null) {
                ended.await();
            } else {
                ended.await(duration.toMillis(), TimeUnit.MILLISECONDS);
            }
        } catch (InterruptedException e) {
            throw e;
        } catch (Exception e) {
            throw new IllegalStateException("closing the subscription failed", e);
        } finally {
            try {
                Runtime.getRuntime().removeShutdownHook(hook);
            } catch (IllegalStateException stopping) {
                // Ctrl-C: the JVM is stopping; the summary still prints
            }
        }
        out.printf(Locale.ROOT, "watched %s for %.1f s: %d changes, %d samples%n", network.name(),
                (System.nanoTime() - started) / 1e9, changes.get(), samples.get());
        out.flush();
        return 0;
    }

    private static void say(PrintWriter out, long started, String text) {
        synchronized (out) {
            out.printf(Locale.ROOT, "[%6.1fs] %s%n", (System.nanoTime() - started) / 1e9, text);
            out.flush();
        }
    }

    /** A number to four significant digits, a vector as its first three elements and its length. */
    static String shortText(Value v) {
        switch (v.type()) {
            case DOUBLE:
                return String.format(Locale.ROOT, "%.4g", v.asDouble());
            case DOUBLES:
                StringJoiner j = new StringJoiner(", ", "[", "]");
                for (int i = 0; i < Math.min(3, v.length()); i++) {
                    j.add(String.format(Locale.ROOT, "%.3g", v.element(i)));
                }
                if (v.length() > 3) {
                    j.add("… " + v.length() + " values");
                }
                return j.toString();
            default:
                String text = v.text();
                return text.length() > 24 ? text.substring(0, 21) + "..." : text;
        }
    }
}

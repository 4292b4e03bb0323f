package org.fdnet.hi.cli;

import java.awt.GraphicsEnvironment;
import java.nio.file.Path;
import java.util.Set;
import java.util.concurrent.Callable;
import javax.swing.SwingUtilities;
import org.fdnet.control.LiveNetwork;
import org.fdnet.control.NetworkUnreachableException;
import org.fdnet.corba.control.RemoteLiveNetwork;
import org.fdnet.hi.app.HiApplication;
import org.fdnet.hi.app.HiWindow;
import org.fdnet.hi.app.RecentFiles;
import org.fdnet.hi.app.WindowScreenshot;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.hi.live.InProcessRun;
import org.fdnet.hi.live.LiveNetworkFinder;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.runtime.engine.RuntimeStartException;
import org.fdnet.tls.TlsOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/** {@code fdnet hi [FILE]}: the graphical and text-based network editor. */
@Command(name = "hi", mixinStandardHelpOptions = true,
        description = {"The Human Interface: edit a network graphically and in text frames (Swing).",
            "A file with problems opens read-only with its problem list.",
            "Live: --attach NAME edits a running network (each edit is sent to it first and shown once executed);",
            "--run starts FILE in this process and attaches to it.",
            "--tls DIR/NAME.p12 attaches to a network whose processes speak mutual TLS (fdnet keys).",
            "With --screenshot, renders the window to a PNG and exits (needs a display, e.g. xvfb-run)."})
public final class HiCommand implements Callable<Integer> {
    @Parameters(arity = "0..1", paramLabel = "FILE", description = "the .fdn network to open")
    Path file;

    @Option(names = "--attach", paramLabel = "NAME", description = "attach to the running network published as NAME")
    String attach;

    @Option(names = "--naming", paramLabel = "CORBALOC",
            description = "with --attach NAME: the naming service to look NAME up in, when it does not run on this machine")
    String naming;

    @Option(names = "--run", description = "run FILE in the editor's process and attach to it (stops when the editor closes)")
    boolean run;

    @Option(names = "--screenshot", paramLabel = "PNG", description = "render the window to this PNG and exit")
    Path screenshot;

    @Option(names = "--size", paramLabel = "WxH", defaultValue = "1280x800", description = "window size (default 1280x800)")
    String size;

    @Option(names = "--select", paramLabel = "MODULE/NODE", description = "select this node (shown in the information panel)")
    String select;

    @Option(names = "--select-connection", paramLabel = "DATA>RELATION",
            description = "select the Reader or Writer between these two nodes (MODULE/NODE>MODULE/NODE)")
    String selectConnection;

    @Option(names = "--highlight", paramLabel = "WHICH", description = "highlight the selected node's ANCESTORS, DESCENDANTS or BOTH")
    GraphScene.Relatives highlight;

    @Option(names = "--hide", paramLabel = "MODULE", split = ",", description = "modules to hide")
    String[] hide = new String[0];

    @Option(names = "--frame", paramLabel = "WHICH",
            description = "open a text frame: NETWORK, MODULE or ADVANCED (of the selected node's module); --screenshot then shows it")
    HiWindow.TextFrame frame;

    @Option(names = "--find", paramLabel = "TEXT", description = "search for TEXT as Ctrl-F does")
    String find;

    @Mixin
    TlsOptions tls;

    @Spec
    CommandSpec spec;

    private javax.swing.JDialog opened;

    @Override
    public Integer call() throws Exception {
        try {
            tls.apply(); // first: a bad key store is named even where no window can open
        } catch (IllegalArgumentException e) {
            spec.commandLine().getErr().println("fdnet hi: --tls: " + e.getMessage());
            return 2;
        }
        if (GraphicsEnvironment.isHeadless()) {
            spec.commandLine().getErr().println("fdnet hi: no display (DISPLAY is not set); run it under X, or xvfb-run for --screenshot");
            return 2;
        }
        if (run && file == null) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--run needs the FILE to run");
        }
        if (run && attach != null) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--run and --attach exclude each other");
        }
        InProcessRun started = null;
        if (run) {
            try {
                started = InProcessRun.start(file);
            } catch (NetworkFileException e) {
                e.problems().forEach(p -> spec.commandLine().getErr().println(p));
                return 1;
            } catch (RuntimeStartException e) {
                spec.commandLine().getErr().println(file + ": the network cannot start:");
                e.problems().forEach(p -> spec.commandLine().getErr().println("  " + p));
                return 1;
            }
            spec.commandLine().getOut().println("running " + started.live().name() + " (" + file + ") in the editor's process");
        }
        try {
            return show(started);
        } finally {
            if (started != null) {
                started.close();
            }
        }
    }

    private int show(InProcessRun started) throws Exception {
        LiveNetwork attached = started == null ? null : started.live();
        if (attach != null) {
            try {
                attached = finder().find(attach);
            } catch (NetworkUnreachableException e) {
                spec.commandLine().getErr().println("fdnet hi --attach " + attach + ": " + e.getMessage());
                return 1;
            }
        }
        HiWindow window = HiApplication.start(file, RecentFiles.forUser());
        LiveNetwork network = attached;
        SwingUtilities.invokeAndWait(() -> {
            window.setSize(parseSize());
            window.setFinder(finder());
            if (network != null) {
                window.attach(network, false);
            }
        });
        Thread.sleep(400);
        SwingUtilities.invokeAndWait(() -> prepare(window));
        if (screenshot == null) {
            HiApplication.awaitClosed(window);
            return 0;
        }
        Thread.sleep(started != null || attach != null ? 1500 : 300); // live: let values arrive and be drawn
        Exception[] failure = new Exception[1];
        SwingUtilities.invokeAndWait(() -> {
            try {
                WindowScreenshot.write(opened == null ? window : opened, screenshot);
                if (opened != null) {
                    opened.dispose();
                }
            } catch (Exception e) {
                failure[0] = e;
            }
            window.dispose();
        });
        if (failure[0] != null) {
            spec.commandLine().getErr().println("fdnet hi: cannot write " + screenshot + ": " + failure[0].getMessage());
            return 1;
        }
        spec.commandLine().getOut().println("wrote " + screenshot);
        return 0;
    }

    /** How {@code --attach} and the editor's Live menu find a running network: by name, HOST:PORT or corbaloc. */
    private LiveNetworkFinder finder() {
        String namingService = naming;
        return name -> RemoteLiveNetwork.attach(name, namingService);
    }

    private java.awt.Dimension parseSize() {
        String[] wh = size.split("x");
        try {
            return new java.awt.Dimension(Integer.parseInt(wh[0]), Integer.parseInt(wh[1]));
        } catch (RuntimeException e) {
            throw new picocli.CommandLine.ParameterException(spec.commandLine(), "--size must be WIDTHxHEIGHT, e.g. 1280x800, not " + size);
        }
    }

    private void prepare(HiWindow window) {
        if (window.current() == null) {
            return;
        }
        GraphScene scene = window.current().scene();
        for (String module : hide) {
            scene.setModuleVisible(module, false);
        }
        if (select != null) {
            NodeRef ref = NodeRef.parse(select, "main");
            scene.select(Set.of(ref));
            if (highlight != null) {
                scene.highlight(ref, highlight);
            }
        }
        if (selectConnection != null) {
            String[] ends = selectConnection.split(">", 2);
            NodeRef data = NodeRef.parse(ends[0].trim(), "main");
            NodeRef relation = NodeRef.parse(ends.length > 1 ? ends[1].trim() : "", "main");
            scene.visibleConnections().stream()
                    .filter(c -> c.connection().data().equals(data) && c.connection().relation().equals(relation))
                    .findFirst().ifPresentOrElse(scene::selectConnection,
                            () -> window.status().error("no Reader or Writer between " + data + " and " + relation));
        }
        window.canvas().fit();
        if (find != null) {
            window.search().open();
            window.search().search(find);
        }
        if (frame != null) {
            opened = window.openTextFrame(frame);
        }
    }
}

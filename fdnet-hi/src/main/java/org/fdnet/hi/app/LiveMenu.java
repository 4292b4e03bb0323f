package org.fdnet.hi.app;

import java.io.IOException;
import java.util.List;
import java.util.Optional;
import javax.swing.Action;
import javax.swing.JCheckBoxMenuItem;
import javax.swing.JMenu;
import javax.swing.JOptionPane;
import javax.swing.SwingUtilities;
import org.fdnet.control.LiveNetwork;
import java.nio.file.Path;
import org.fdnet.corba.DistributedRun;
import org.fdnet.hi.live.DeployPreviewDialog;
import org.fdnet.hi.live.EditorRun;
import org.fdnet.hi.live.RunChoice;
import org.fdnet.hi.live.LiveSession;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.viewer.ui.ViewerWindow;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Live: run the open network (on this machine, over its hosts, or on the simulated RoQ) and stop it; attach to a
 * running network and detach; collect changes and deploy them through the preview (also from
 * a network edited offline); plot the selected Datas in the viewer; save the running network with what it
 * built by itself.
 */
final class LiveMenu {
    private static final Logger LOG = LoggerFactory.getLogger(LiveMenu.class);
    private static final String DEFAULT_LOGGER = "127.0.0.1:5556";

    private final HiWindow window;
    private final JMenu menu = new JMenu("Live");
    private final Action attach;
    private final Action detach;
    private final JCheckBoxMenuItem collect = new JCheckBoxMenuItem("Collect Changes (Deploy Later)");
    private final Action deploy;
    private final Action discard;
    private final Action plot;
    private final Action saveRunning;
    private final Action runNetwork;
    private final Action stopNetwork;
    private String loggerAddress = DEFAULT_LOGGER;
    private RunChoice lastChoice = RunChoice.thisMachine();
    private EditorRun running; // the run started here, until Stop

    LiveMenu(HiWindow window) {
        this.window = window;
        menu.setName("menu.live");
        runNetwork = MenuItems.action("Run Open Network…", "control shift R", this::askAndRun);
        stopNetwork = MenuItems.action("Stop Network", null, this::stop);
        attach = MenuItems.action("Attach to Running Network…", "control shift A", this::attach);
        detach = MenuItems.action("Detach", null, () -> window.live().close());
        deploy = MenuItems.action("Deploy to Running Network…", "control shift D", this::deploy);
        discard = MenuItems.action("Discard Pending Changes", null, () -> {
            window.live().discardPending();
            if (window.live() != null) {
                window.status().info("Pending changes discarded; live again");
            }
            window.refreshTitle();
            refresh();
        });
        plot = MenuItems.action("Plot Selected Data…", "control shift P", this::plot);
        saveRunning = MenuItems.action("Save Running Network As…", null, this::saveRunning);
        collect.setName("live.collect");
        collect.addActionListener(e -> toggleCollect());
        menu.add(runNetwork).setName("live.run");
        menu.add(stopNetwork).setName("live.stop");
        menu.addSeparator();
        menu.add(attach).setName("live.attach");
        menu.add(detach).setName("live.detach");
        menu.addSeparator();
        menu.add(collect);
        menu.add(deploy).setName("live.deploy");
        menu.add(discard).setName("live.discard");
        menu.addSeparator();
        menu.add(plot).setName("live.plot");
        menu.add(saveRunning).setName("live.saveRunning");
    }

    JMenu menu() {
        return menu;
    }

    void refresh() {
        LiveSession live = window.live();
        boolean open = window.current() != null;
        runNetwork.setEnabled(running == null && open && window.current().file() != null);
        stopNetwork.setEnabled(running != null);
        attach.setEnabled(live == null);
        detach.setEnabled(live != null);
        collect.setEnabled(live != null);
        collect.setSelected(live != null && live.collecting());
        deploy.setEnabled(open && (live == null || live.collecting()));
        deploy.putValue(Action.NAME, live == null ? "Deploy to Running Network…" : "Deploy Pending Changes…");
        discard.setEnabled(live != null && live.collecting());
        plot.setEnabled(open);
        saveRunning.setEnabled(live != null);
    }

    /** Run: where (a dialog), then {@link #run}. The network runs from its file, so it must be saved. */
    private void askAndRun() {
        OpenNetwork open = window.current();
        if (open.unsaved()) {
            window.status().error("Save the network first: it runs from its file");
            return;
        }
        RunChoice choice = RunNetworkDialog.ask(window, open.file().getFileName().toString(),
                DistributedRun.spansHosts(open.editor().network()), lastChoice);
        if (choice != null) {
            lastChoice = choice;
            run(choice);
        }
    }

    /** Starts the open network's file where {@code choice} says and attaches to it as soon as it runs. */
    void run(RunChoice choice) {
        Path file = window.current().file();
        window.status().info("Starting " + file.getFileName() + " " + choice.describe() + "…");
        runNetwork.setEnabled(false);
        Thread starter = new Thread(() -> {
            try {
                EditorRun started = EditorRun.start(file, choice, 120_000);
                SwingUtilities.invokeLater(() -> {
                    running = started;
                    if (window.attach(started.live(), false)) {
                        window.status().info("Running " + started.live().name() + " " + choice.describe()
                                + "; Live → Stop Network ends it");
                    }
                    refresh();
                });
            } catch (IllegalStateException | InterruptedException e) {
                LOG.warn("{} did not start {}", file, choice.describe(), e);
                SwingUtilities.invokeLater(() -> {
                    window.status().error("Cannot run " + file.getFileName() + " " + choice.describe() + ": "
                            + e.getMessage());
                    refresh();
                });
            }
        }, "fdnet-hi-run-start");
        starter.setDaemon(true);
        starter.start();
    }

    /** Stop: ends every host's part of the run started here, commits its events, and goes offline. */
    void stop() {
        EditorRun stopping = running;
        if (stopping == null) {
            return;
        }
        running = null;
        stopNetwork.setEnabled(false);
        window.status().info("Stopping " + stopping.live().name() + "…");
        Thread stopper = new Thread(() -> {
            int exit;
            try {
                exit = stopping.stop();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                exit = -1;
            }
            int code = exit;
            SwingUtilities.invokeLater(() -> {
                if (window.live() != null) {
                    window.live().close();
                }
                window.status().info("Stopped " + stopping.live().name() + (code == 0 ? "" : " (exit " + code + ")"));
                refresh();
            });
        }, "fdnet-hi-run-stop");
        stopper.setDaemon(true);
        stopper.start();
    }

    /** The run started from this menu, or {@code null}. */
    EditorRun running() {
        return running;
    }

    private void attach() {
        String name = ask("Attach to the running network named (or at HOST:PORT):");
        LiveNetwork network = name == null ? null : find(name);
        if (network != null) {
            window.attach(network, false);
        }
    }

    /** Attached and collecting: the preview of the pending changes. Offline: attach collecting, then the preview. */
    private void deploy() {
        if (window.live() == null) {
            String name = ask("Deploy the changes shown here to the running network named:");
            LiveNetwork network = name == null ? null : find(name);
            if (network == null || !window.attach(network, true)) {
                return;
            }
        }
        preview();
    }

    private void preview() {
        LiveSession live = window.live();
        ChangeOutcome outcome = DeployPreviewDialog.show(window, live);
        if (outcome != null && outcome.executed()) {
            window.status().info("Deployed to " + live.name() + ": " + outcome.description() + "; live again");
        } else {
            window.status().info("Not deployed; the changes stay pending (Live → Deploy, or Discard)");
        }
        window.refreshTitle();
        refresh();
    }

    private void toggleCollect() {
        LiveSession live = window.live();
        if (live == null) {
            return;
        }
        if (collect.isSelected()) {
            live.startCollecting();
            window.status().info("Collecting changes for " + live.name() + "; Live → Deploy sends them together");
        } else if (live.pending().isEmpty()) {
            live.discardPending();
            window.status().info("Live again: edits go to " + live.name() + " first");
        } else {
            preview();
        }
        window.refreshTitle();
        refresh();
    }

    /**
     * The selected Datas in the Network State Viewer, live from the logger: the one recording the attached network
     * when the network tells where viewers reach it (fdnet demo does), else asked for (and remembered).
     */
    private void plot() {
        List<String> names = window.current().scene().selection().stream()
                .filter(r -> window.current().editor().network().node(r).kind() == NodeKind.DATA)
                .map(NodeRef::toString).toList();
        if (names.isEmpty()) {
            window.status().error("Select one or more Data nodes to plot");
            return;
        }
        LiveSession live = window.live();
        if (live == null) {
            askAndOpenViewer(names);
            return;
        }
        window.status().info("Asking " + live.name() + " where its logger is…");
        Thread asker = new Thread(() -> {
            Optional<String> address;
            try {
                address = live.loggerViewerAddress();
            } catch (RuntimeException e) {
                LOG.warn("{} did not say where its logger is", live.name(), e);
                address = Optional.empty();
            }
            Optional<String> known = address;
            SwingUtilities.invokeLater(() -> {
                if (known.isPresent()) {
                    openViewer(known.get(), names);
                } else {
                    askAndOpenViewer(names);
                }
            });
        }, "fdnet-hi-plot-ask");
        asker.setDaemon(true);
        asker.start();
    }

    private void askAndOpenViewer(List<String> names) {
        String address = (String) JOptionPane.showInputDialog(window, "The logger's viewer service (HOST:PORT):",
                "Plot " + names.size() + " Data", JOptionPane.QUESTION_MESSAGE, null, null, loggerAddress);
        if (address == null || address.isBlank()) {
            return;
        }
        loggerAddress = address.trim();
        openViewer(loggerAddress, names);
    }

    private void openViewer(String logger, List<String> names) {
        window.status().info("Opening the viewer on " + names + " from the logger at " + logger + "…");
        Thread opener = new Thread(() -> {
            try {
                ViewerWindow.open(logger, names);
                SwingUtilities.invokeLater(() -> window.status().info("Plotting " + names + " from " + logger));
            } catch (IOException | IllegalArgumentException e) {
                LOG.warn("the viewer on {} did not open", logger, e);
                SwingUtilities.invokeLater(() -> window.status().error("Cannot plot from the logger at " + logger + ": "
                        + e.getMessage()));
            }
        }, "fdnet-hi-plot");
        opener.setDaemon(true);
        opener.start();
    }

    /** Reads the running network once more (so it holds all it built by itself), then Save As. */
    private void saveRunning() {
        if (window.live().followNow()) {
            window.fileMenu().saveAs();
        }
    }

    private String ask(String question) {
        String answer = JOptionPane.showInputDialog(window, question, "Running network", JOptionPane.QUESTION_MESSAGE);
        return answer == null || answer.isBlank() ? null : answer.trim();
    }

    private LiveNetwork find(String name) {
        try {
            return window.finder().find(name);
        } catch (RuntimeException e) {
            LOG.warn("cannot attach to {}", name, e);
            window.status().error("Cannot reach the running network " + name + ": " + e.getMessage());
            return null;
        }
    }
}

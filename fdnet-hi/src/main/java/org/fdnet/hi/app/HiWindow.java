package org.fdnet.hi.app;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.nio.file.Path;
import java.util.List;
import javax.swing.JComponent;
import javax.swing.JFrame;
import javax.swing.JMenuBar;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JSplitPane;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;
import org.fdnet.hi.edit.EditorListener;
import org.fdnet.hi.graph.GraphCanvas;
import org.fdnet.hi.graph.SceneListener;
import org.fdnet.hi.live.LiveNetworkFinder;
import org.fdnet.hi.live.LiveSession;
import org.fdnet.hi.live.LiveSessionListener;
import org.fdnet.hi.live.RunningModulesPanel;
import org.fdnet.control.LiveNetwork;
import org.fdnet.netinfo.ModuleCounts;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.Problem;
import org.fdnet.viewer.legible.LegibleFont;

/**
 * The editor's main window. It shows either one open network (module bar and search bar above the graphic
 * panel, the node information panel at the right) or, for a file with problems, the read-only
 * {@link ProblemView}; the status bar is always at the bottom. The menus live in {@link FileMenu},
 * {@link EditMenu}, {@link ViewMenu} and {@link LiveMenu}. Attached to a running network (a {@link LiveSession}),
 * the side panel also lists the running modules and the title says "live" (or "collecting", or "offline" once
 * the network is lost).
 */
public final class HiWindow extends JFrame {
    private static final org.slf4j.Logger LOG = org.slf4j.LoggerFactory.getLogger(HiWindow.class);
    private final StatusBar status = new StatusBar();
    private boolean illegibleNamesSaid;
    private final RecentFiles recent;
    private final JPanel content = new JPanel(new BorderLayout());
    private OpenNetwork current;
    private GraphCanvas canvas;
    private SearchBar search;
    private ProblemView problems;
    private Path problemFile;
    private final FileMenu fileMenu;
    private final EditMenu editMenu;
    private final ViewMenu viewMenu;
    private final LiveMenu liveMenu;
    private final JPanel liveSlot = new JPanel(new BorderLayout());
    private NodeInfoPanel info;
    private LiveSession live;
    private RunningModulesPanel runningModules;
    private String offline;
    private LiveNetworkFinder finder = name -> org.fdnet.corba.control.RemoteLiveNetwork.attach(name, null);

    public HiWindow(RecentFiles recent) {
        super("FDNet editor");
        this.recent = recent;
        setDefaultCloseOperation(WindowConstants.DO_NOTHING_ON_CLOSE);
        addWindowListener(new java.awt.event.WindowAdapter() {
            @Override
            public void windowClosing(java.awt.event.WindowEvent e) {
                fileMenu.quit();
            }
        });
        fileMenu = new FileMenu(this);
        editMenu = new EditMenu(this);
        viewMenu = new ViewMenu(this);
        liveMenu = new LiveMenu(this);
        JMenuBar bar = new JMenuBar();
        bar.add(fileMenu.menu());
        bar.add(editMenu.menu());
        bar.add(viewMenu.menu());
        bar.add(liveMenu.menu());
        setJMenuBar(bar);
        getContentPane().add(content, BorderLayout.CENTER);
        getContentPane().add(status, BorderLayout.SOUTH);
        setSize(new Dimension(1280, 800));
        show(OpenNetwork.empty());
    }

    // ---------------------------------------------------------------- what is shown

    public OpenNetwork current() {
        return current;
    }

    public GraphCanvas canvas() {
        return canvas;
    }

    public SearchBar search() {
        return search;
    }

    /** The read-only view of a file with problems, or {@code null}. */
    public ProblemView problems() {
        return problems;
    }

    public StatusBar status() {
        return status;
    }

    FileMenu fileMenu() {
        return fileMenu;
    }

    RecentFiles recent() {
        return recent;
    }

    /**
     * Draws {@code network}'s names in a font that has their characters; when no installed font has, says so
     * once (per window) in the status bar, naming the package to install — after what opening it says.
     */
    private void legibleNames(OpenNetwork network) {
        LegibleFont.Choice c = NamesFont.forGraph(network.editor().network());
        canvas.setNamesFont(c.font());
        if (NamesFont.fitSwingDefault(network.editor().network())) {
            SwingUtilities.updateComponentTreeUI(this);
        }
        if (!c.legible() && !illegibleNamesSaid) {
            illegibleNamesSaid = true;
            SwingUtilities.invokeLater(() -> status.error(c.warning()));
        }
    }

    /** The font the graph draws names in (tests: every name displayable). */
    public java.awt.Font namesFont() {
        return canvas == null ? null : canvas.namesFont();
    }

    /** Opens {@code file}: its network, or its problems read-only. */
    public void open(Path file) {
        try {
            OpenNetwork opened = OpenNetwork.load(file);
            show(opened);
            recent.add(file);
            refreshMenus();
            status.info("Opened " + file + (opened.layoutWarning() == null ? "" : " — " + opened.layoutWarning()));
        } catch (NetworkFileException e) {
            showProblems(file, e.problems());
        }
    }

    public void show(OpenNetwork network) {
        if (live != null) {
            live.close();
        }
        offline = null;
        current = network;
        problems = null;
        problemFile = null;
        canvas = new GraphCanvas(network.scene());
        legibleNames(network);
        search = new SearchBar(network.scene(), canvas);
        info = new NodeInfoPanel(network.scene(), network.editor());
        info.reportTo(status);
        network.editor().addEditorListener(new EditorListener() {
            @Override
            public void historyChanged() {
                refreshTitle();
                refreshMenus();
            }

            @Override
            public void refused(String reason) {
                status.error("Refused: " + reason);
            }
        });
        network.scene().addListener(new SceneListener() {
            @Override
            public void sceneChanged() {
                refreshTitle();
            }

            @Override
            public void selectionChanged() {
                // the info panel follows the selection itself
            }
        });
        canvas.onActivate(editMenu::openNode);
        canvas.onPopup((p, ref) -> editMenu.popup(canvas, p, ref));
        JPanel top = new JPanel(new BorderLayout());
        top.add(new ModuleBar(network.scene()), BorderLayout.NORTH);
        top.add(search, BorderLayout.SOUTH);
        JPanel graph = new JPanel(new BorderLayout());
        graph.add(top, BorderLayout.NORTH);
        graph.add(canvas, BorderLayout.CENTER);
        JPanel sidePanel = new JPanel(new BorderLayout());
        sidePanel.add(new ModuleTreePanel(network.scene()), BorderLayout.NORTH);
        sidePanel.add(info, BorderLayout.CENTER);
        liveSlot.removeAll();
        sidePanel.add(liveSlot, BorderLayout.SOUTH);
        JScrollPane side = new JScrollPane(sidePanel);
        side.setPreferredSize(new Dimension(320, 400));
        JSplitPane split = new JSplitPane(JSplitPane.HORIZONTAL_SPLIT, graph, side);
        split.setResizeWeight(1);
        replaceContent(split);
        refreshTitle();
        refreshMenus();
        javax.swing.SwingUtilities.invokeLater(canvas::fit);
    }

    public void showProblems(Path file, List<Problem> list) {
        if (live != null) {
            live.close();
        }
        current = null;
        canvas = null;
        search = null;
        problemFile = file;
        problems = new ProblemView(file, list);
        replaceContent(problems);
        setTitle(file.getFileName() + " (read-only: " + list.size() + " problems) — FDNet editor");
        status.error(list.size() + " problems in " + file + "; the first: " + list.get(0));
        status.summary(" ");
        refreshMenus();
    }

    private void replaceContent(JComponent c) {
        content.removeAll();
        content.add(c, BorderLayout.CENTER);
        content.revalidate();
        content.repaint();
    }

    /** Menus follow the history and what is open; not called while dragging (that changes neither). */
    void refreshMenus() {
        fileMenu.refresh();
        editMenu.refresh();
        viewMenu.refresh();
        liveMenu.refresh();
    }

    /** Title (with * while unsaved) and the network in numbers. */
    void refreshTitle() {
        if (current == null) {
            return;
        }
        String networkName = current.editor().network().name() == null ? "untitled" : current.editor().network().name();
        String name = current.file() == null ? networkName + " (not saved)"
                : networkName + " (" + current.file().getFileName() + ")";
        String state = live == null ? offline == null ? "" : " (" + offline + ")"
                : live.collecting() ? " (collecting changes for " + live.name() + ")" : " (live: " + live.name() + ")";
        setTitle((current.unsaved() ? "*" : "") + name + state + " — FDNet editor");
        ModuleCounts t = current.editor().network().totalCounts();
        status.summary(current.editor().network().modules().size() + " modules · " + t.datas() + " Datas · "
                + t.relations() + " Relations · " + t.readers() + " Readers · " + t.writers() + " Writers");
    }

    /** Asks before edits are lost; true when the caller may go on (saved, discarded, or nothing to lose). */
    boolean mayDiscard() {
        if (current == null || !current.unsaved()) {
            return true;
        }
        int answer = JOptionPane.showConfirmDialog(this, "Save the changes to "
                        + (current.file() == null ? "this new network" : current.file().getFileName()) + "?",
                "Unsaved changes", JOptionPane.YES_NO_CANCEL_OPTION, JOptionPane.WARNING_MESSAGE);
        if (answer == JOptionPane.YES_OPTION) {
            return fileMenu.save();
        }
        return answer == JOptionPane.NO_OPTION;
    }

    /** Opens one of the thesis's text frames (for the selected node's module) and returns it. */
    public javax.swing.JDialog openTextFrame(TextFrame which) {
        return switch (which) {
            case NETWORK -> editMenu.openNetworkFrame();
            case MODULE -> editMenu.openModuleFrame(false);
            case ADVANCED -> editMenu.openModuleFrame(true);
        };
    }

    /** The text frames: the Network frame, the Basic and the Advanced Module frame. */
    public enum TextFrame { NETWORK, MODULE, ADVANCED }

    // ---------------------------------------------------------------- live mode

    /** The attachment to a running network, or {@code null} when offline. */
    public LiveSession live() {
        return live;
    }

    /** The running modules of the attached network, or {@code null} when offline. */
    public RunningModulesPanel runningModules() {
        return runningModules;
    }

    /** How Attach and Deploy find a running network by name (default: its control object, on this machine or at HOST:PORT). */
    public void setFinder(LiveNetworkFinder finder) {
        this.finder = finder;
    }

    LiveNetworkFinder finder() {
        return finder;
    }

    /**
     * Attaches the editor to {@code network}. Live: the editor shows the running network (the open one follows it
     * and keeps its layout when it has the same name; else its snapshot opens, laid out afresh), and every edit
     * goes there first. Collecting: the editor keeps what it shows, and the difference is pending until deployed.
     * Returns false (and lets go of the network) when the user would not discard unsaved changes.
     */
    public boolean attach(LiveNetwork network, boolean collecting) {
        if (live != null) {
            live.close();
        }
        try {
            if (!collecting && (current == null || !java.util.Objects.equals(current.editor().network().name(), network.name())
                    || current.unsaved())) {
                if (!mayDiscard()) {
                    network.close();
                    return false;
                }
                show(OpenNetwork.running(network.snapshot()));
            }
            live = LiveSession.attach(network, current.editor(), current.scene(), new LiveView(), collecting);
        } catch (RuntimeException e) {
            LOG.warn("attaching to {} failed", network.name(), e);
            network.close();
            status.error("Cannot attach to " + network.name() + ": " + e.getMessage());
            return false;
        }
        offline = null;
        runningModules = new RunningModulesPanel(live, current.editor().network());
        liveSlot.add(runningModules, BorderLayout.CENTER);
        liveSlot.revalidate();
        info.setLive(live);
        refreshTitle();
        refreshMenus();
        status.info((collecting ? "Collecting changes for " : "Attached to ") + network.name()
                + (collecting ? "; Live → Deploy sends them" : "; every edit goes to the running network first"));
        return true;
    }

    /** What the session tells the window: status lines, module states, its end. */
    private final class LiveView implements LiveSessionListener {
        @Override
        public void info(String message) {
            status.info(message);
        }

        @Override
        public void error(String message) {
            status.error(message);
        }

        @Override
        public void modulesChanged(java.util.Set<String> loaded, java.util.Set<String> held) {
            if (runningModules != null) {
                runningModules.show(loaded, held);
            }
        }

        @Override
        public void ended(boolean lost, String reason) {
            live = null;
            runningModules = null;
            liveSlot.removeAll();
            liveSlot.revalidate();
            liveSlot.repaint();
            if (info != null) {
                info.setLive(null);
            }
            if (lost) {
                offline = "offline: " + reason;
                status.error("The running network is gone (" + reason + "); editing offline with its last state");
            } else {
                offline = null;
                status.info("Detached: " + reason.replaceFirst("^detached from ", "") + " keeps running");
            }
            refreshTitle();
            refreshMenus();
        }
    }

    Path problemFile() {
        return problemFile;
    }
}

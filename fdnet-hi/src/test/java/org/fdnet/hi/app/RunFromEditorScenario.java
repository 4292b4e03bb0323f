package org.fdnet.hi.app;

import java.awt.Window;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import javax.swing.JButton;
import javax.swing.JDialog;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.corba.OrbSettings;
import org.fdnet.hi.live.LiveTestNetwork;
import org.fdnet.netinfo.NodeRef;

/**
 * Live → Run Open Network… and Stop Network, driven like a user on a real display (run in a child JVM by
 * {@link RunFromEditorGuiTest}): a network of this machine runs from the dialog, the editor attaches at once and
 * shows it running, Stop ends it and the editor goes offline; then a network whose Datas and Relation live on host
 * {@code flyer} (a real {@code fdnet host} with its naming service) runs distributed through the naming service
 * typed in the dialog, and Stop ends the flyer's part too. Prints "SCENARIO PASSED" and exits 0, or what failed.
 */
public final class RunFromEditorScenario {
    private static final String LOCAL = """
            <?xml version="1.0" encoding="UTF-8"?>
            <cnet name="editor-local">
                <dstructure><name>Level</name><host>localhost</host><path></path>
                    <class>org.fdnet.runtime.library.DoubleData</class></dstructure>
                <pstructure><name>Source</name><host>localhost</host><path></path>
                    <class>org.fdnet.runtime.library.Expression</class>
                    <param name="period" type="long">50</param><param name="expression">t</param></pstructure>
                <connection><write><data>Level</data><proc>Source</proc></write></connection>
            </cnet>
            """;
    private static final String SPREAD = LOCAL.replace("editor-local", "editor-spread")
            .replace("<host>localhost</host>", "<host>flyer</host>");

    private final HiWindow window;

    private RunFromEditorScenario(HiWindow window) {
        this.window = window;
    }

    public static void main(String[] args) {
        ScenarioProcess.runAndExit(prefs -> {
            Path dir = Files.createTempDirectory("fdnet-run-from-editor");
            Path local = Files.writeString(dir.resolve("editor-local.fdn"), LOCAL);
            Path spread = Files.writeString(dir.resolve("editor-spread.fdn"), SPREAD);
            List<FdnetChildProcess> processes = new ArrayList<>();
            try {
                int port = FdnetChildProcess.freePort();
                processes.add(FdnetChildProcess.start("naming", List.of("naming", "--port", Integer.toString(port)),
                        "fdnet naming ready", 60_000));
                String naming = OrbSettings.namingCorbaloc(OrbSettings.LOOPBACK, port);
                FdnetChildProcess flyer = FdnetChildProcess.start("host flyer",
                        List.of("host", "--name", "flyer", "--naming", naming), "fdnet host flyer ready", 60_000);
                processes.add(flyer);
                HiWindow window = HiApplication.start(local, new RecentFiles(prefs));
                RunFromEditorScenario scenario = new RunFromEditorScenario(window);
                scenario.runAndStop("editor-local", null);
                LiveTestNetwork.edt(() -> {
                    window.open(spread);
                    return null;
                });
                scenario.runAndStop("editor-spread", naming);
                ShowingComponents.check(flyer.isAlive(), "the flyer host serves on after the run stopped");
            } finally {
                for (int i = processes.size() - 1; i >= 0; i--) {
                    processes.get(i).close();
                }
            }
        });
    }

    /** Run from the dialog (distributed through {@code naming} when given), check it runs, Stop, check it stopped. */
    private void runAndStop(String network, String naming) throws Exception {
        JMenuItem run = menuItem(window, "live.run");
        SwingUtilities.invokeLater(run::doClick);
        waitFor("the Run dialog", () -> dialog() != null);
        LiveTestNetwork.edt(() -> {
            JDialog d = dialog();
            if (naming != null) {
                ShowingComponents.find(d, JTextField.class, "run.naming").setText(naming);
            }
            ShowingComponents.find(d, JButton.class, "OK").doClick();
            return null;
        });
        waitFor(network + " running and the editor attached to it", () -> window.live() != null
                && window.live().name().equals(network));
        waitFor(network + "'s running definition shown", () -> window.current().editor().network()
                .node(new NodeRef("main", "Source")) != null);
        ShowingComponents.check(LiveTestNetwork.edt(() -> window.status().message().startsWith("Running " + network)),
                "the status says it runs");
        ShowingComponents.check(LiveTestNetwork.edt(() -> !menuItem(window, "live.run").isEnabled()
                && menuItem(window, "live.stop").isEnabled()), "Run is off and Stop on while it runs");
        LiveTestNetwork.edt(() -> {
            menuItem(window, "live.stop").doClick();
            return null;
        });
        waitFor(network + " stopped and the editor offline", () -> window.live() == null
                && menuItem(window, "live.run").isEnabled() && !menuItem(window, "live.stop").isEnabled());
    }

    /** The editor's menu item named {@code name} (Swing thread). */
    static JMenuItem menuItem(HiWindow window, String name) {
        for (int i = 0; i < window.getJMenuBar().getMenuCount(); i++) {
            JMenu menu = window.getJMenuBar().getMenu(i);
            for (int j = 0; j < menu.getItemCount(); j++) {
                JMenuItem item = menu.getItem(j);
                if (item != null && name.equals(item.getName())) {
                    return item;
                }
            }
        }
        throw new AssertionError("no menu item " + name);
    }

    /** The showing dialog, or {@code null}. */
    static JDialog dialog() {
        return (JDialog) Arrays.stream(Window.getWindows()).filter(w -> w instanceof JDialog d && d.isShowing())
                .findFirst().orElse(null);
    }

    private void waitFor(String what, java.util.function.BooleanSupplier condition) throws Exception {
        ShowingComponents.waitFor(window, what, condition);
    }
}

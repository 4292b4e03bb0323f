package org.fdnet.hi.app;

import static org.fdnet.hi.live.LiveTestNetwork.LIB;
import static org.fdnet.hi.live.LiveTestNetwork.ref;

import java.awt.Component;
import java.awt.Container;
import java.awt.Point;
import java.awt.Robot;
import java.awt.Window;
import java.awt.event.InputEvent;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.List;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import javax.swing.AbstractButton;
import javax.swing.JDialog;
import javax.swing.JList;
import javax.swing.JMenu;
import javax.swing.JMenuItem;
import javax.swing.JTable;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.fdnet.control.LiveNetwork;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.hi.live.InProcessRun;
import org.fdnet.hi.live.LiveTestNetwork;
import org.fdnet.hi.live.RunningModulesPanel;
import org.fdnet.logger.InProcessLogger;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.xml.LayoutRepository;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.viewer.ui.ViewerWindow;

/**
 * The editor in live mode, driven like a user on a real display (run in a child JVM by {@link LiveEditorGuiTest})
 * against a network running in the same JVM and logging to a real logger: an accepted edit, two Datas plotted in
 * the viewer, a refused edit (Figure 37), a filter the network
 * builds by itself (Figure 31), a module unloaded and loaded again from the module list, a value sent to a Data,
 * the deploy preview refused and then applied all together, saving the running network, and losing it. Writes
 * its screenshots to the directory given as argument. Prints "SCENARIO PASSED" and exits 0, or what failed and 1.
 */
public final class LiveEditorScenario {
    private static final NodeRef GAIN = ref("Gain");

    private final HiWindow window;
    private final InProcessRun run;
    private final Path images;
    private final Robot robot;

    private LiveEditorScenario(HiWindow window, InProcessRun run, Path images) throws Exception {
        this.window = window;
        this.run = run;
        this.images = images;
        this.robot = new Robot();
        robot.setAutoDelay(30);
    }

    public static void main(String[] args) throws Exception {
        Path images = Path.of(args[0]);
        ScenarioProcess.runAndExit(prefs -> {
            try (InProcessLogger logger = InProcessLogger.throwaway()) {
                LoggerClient events = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(), "live editor"));
                try (InProcessRun run = InProcessRun.start(LiveTestNetwork.definition(),
                        RuntimeOptions.defaults().workerThreads(2).sink(events), Optional.of(logger.viewerAddress()))) {
                    HiWindow window = HiApplication.start(null, new RecentFiles(prefs));
                    new LiveEditorScenario(window, run, images).run(logger.viewerAddress());
                } finally {
                    events.close();
                }
            }
        });
    }

    private LiveNetwork network() {
        return run.live();
    }

    private void run(String loggerAddress) throws Exception {
        waitFor("the window is shown", () -> window.isShowing() && window.canvas().getWidth() > 0);
        check(edt(() -> window.attach(network(), false)), "attached");
        waitFor("the running network is shown", () -> window.current().editor().network().node(GAIN) != null
                && window.getTitle().contains("live: live-editor-test"));
        waitFor("the module list shows Wave running",
                () -> RunningModulesPanel.RUNNING.equals(window.runningModules().stateOf("Wave")));
        waitFor("Wave/signal's live value drawn", () -> window.current().scene().liveValue(ref("Wave/signal")) != null);
        edt(() -> {
            window.canvas().fit();
            return null;
        });

        acceptedEdit();
        plot(loggerAddress);
        refusedEdit();
        selfOrganisedChange();
        moduleUnloadAndLoad();
        sendValue();
        deployPreview();
        saveRunningNetwork();
        lostNetwork();
    }

    /** The gain's parameter changed in the information panel: executed there, then shown here. */
    private void acceptedEdit() throws Exception {
        edt(() -> {
            window.current().scene().select(Set.of(GAIN));
            JTable table = find(window, JTable.class, "info.parameters");
            table.setValueAt("3 * in0", 0, 2);
            return null;
        });
        clickButton(window, "info.applyNode");
        waitFor("the edit is executed and shown", () -> "3 * in0".equals(
                window.current().editor().network().node(GAIN).parameter("expression")));
        check("3 * in0".equals(network().snapshot().node(GAIN).parameter("expression")), "the running network has it");
        check(edt(() -> window.status().message()).contains("Executed by live-editor-test"), "the status bar says executed");
        shot("hi-live.png");
    }

    /**
     * Two Datas selected → Live → Plot: the running network says where its logger is, so the viewer opens on them
     * without asking and draws their logged values.
     */
    private void plot(String loggerAddress) throws Exception {
        edt(() -> {
            window.current().scene().select(Set.of(ref("Wave/signal"), ref("Out")));
            return null;
        });
        SwingUtilities.invokeLater(() -> menuItem("live.plot").doClick());
        AtomicReference<ViewerWindow> viewer = new AtomicReference<>();
        waitFor("the viewer opened", () -> {
            for (Window w : Window.getWindows()) {
                if (w instanceof ViewerWindow v && v.isShowing()) {
                    viewer.set(v);
                    return true;
                }
            }
            return false;
        });
        waitFor("the viewer draws both Datas' values", () -> viewer.get().liveData().series().size() == 2
                && viewer.get().liveData().acceptedEvents() > 20);
        check(Arrays.stream(Window.getWindows()).noneMatch(w -> w instanceof JDialog d && d.isShowing()
                && d.getTitle().startsWith("Plot")), "no dialog asked for the logger's address");
        check(edt(() -> window.status().message()).contains(loggerAddress), "the status bar names the run's logger");
        shot(viewer.get(), "hi-live-plot.png");
        edt(() -> {
            viewer.get().dispose();
            window.current().scene().select(Set.of(GAIN));
            return null;
        });
    }

    /** A class the network cannot load: refused there, so nothing changes here and the status bar says why. */
    private void refusedEdit() throws Exception {
        NetworkInfo before = edt(() -> window.current().editor().network().copy());
        edt(() -> {
            find(window, JTextField.class, "info.class").setText("org.fdnet.NoSuchRelation");
            return null;
        });
        clickButton(window, "info.applyNode");
        waitFor("the refusal in the status bar", () -> window.status().message().startsWith("Refused: the running network refused it"));
        check(edt(() -> window.status().message()).contains("org.fdnet.NoSuchRelation"), "the reason names the class");
        check(edt(() -> window.current().editor().network().copy()).equals(before), "the view is untouched");
        check(network().snapshot().node(GAIN).className().equals(LIB + "Expression"), "the running network is untouched");
        shot("hi-live-refused.png");
        edt(() -> {
            window.current().scene().select(Set.of());
            return null;
        });
    }

    /** Another tool plugs in a sensor; the Organizer builds its filter, and both appear in the editor, placed. */
    private void selfOrganisedChange() throws Exception {
        NetworkInfo base = network().snapshot();
        NetworkInfo edited = base.copy();
        edited.addNode("main", NodeInfo.data("Wheel", LIB + "DoubleSensor"));
        check(network().apply("plug a wheel sensor", base, edited).executed(), "the sensor is plugged in");
        waitFor("the filter the network built appears", () -> window.current().scene().bounds(ref("Wheel filter")) != null
                && window.current().scene().bounds(ref("Wheel filtered")) != null);
        edt(() -> {
            window.current().scene().select(Set.of(ref("Wheel filter")));
            window.canvas().fit();
            return null;
        });
        waitFor("the status bar tells what the network built", () -> window.status().message().contains("+ node main/Wheel"));
        shot("hi-live-self-organised.png");
    }

    private void moduleUnloadAndLoad() throws Exception {
        edt(() -> {
            window.runningModules().select("Wave");
            return null;
        });
        clickButton(window, "live.unload");
        waitFor("Wave shown as not loaded", () -> RunningModulesPanel.NOT_LOADED.equals(window.runningModules().stateOf("Wave")));
        check(!network().loadedModules().contains("Wave"), "Wave is unloaded in the running network");
        clickButton(window, "live.load");
        waitFor("Wave shown running again", () -> RunningModulesPanel.RUNNING.equals(window.runningModules().stateOf("Wave")));
        check(network().loadedModules().contains("Wave"), "Wave is loaded again in the running network");
    }

    private void sendValue() throws Exception {
        edt(() -> {
            window.current().scene().select(Set.of(ref("Out")));
            find(window, JTextField.class, "info.sendValue").setText("42");
            return null;
        });
        clickButton(window, "info.send");
        waitFor("the value is sent", () -> window.status().message().contains("send main/Out=42: executed"));
    }

    /** Collect two changes; the preview lists them; a conflicting change elsewhere refuses both; then both apply. */
    private void deployPreview() throws Exception {
        edt(() -> {
            menuItem("live.collect").doClick();
            var editor = window.current().editor();
            editor.setParameters(GAIN, List.of(Parameter.named("expression", "4 * in0")));
            editor.addNode("main", NodeInfo.data("Extra", LIB + "DoubleData"));
            return null;
        });
        check(edt(() -> window.getTitle()).contains("collecting changes for live-editor-test"), "the title says collecting");
        check(network().snapshot().node(ref("Extra")) == null, "collected, not sent");

        // another tool changes the gain meanwhile: the pending change to it no longer fits
        NetworkInfo base = network().snapshot();
        NetworkInfo other = base.copy();
        other.setParameters(GAIN, List.of(Parameter.named("expression", "5 * in0")));
        check(network().apply("another tool", base, other).executed(), "the other tool's change executed");

        JDialog preview = openPreview();
        List<String> entries = edt(() -> entries(preview));
        check(entries.contains("+ node main/Extra") && entries.contains("~ main/Gain parameter expression 3 * in0 → 4 * in0"),
                "the preview lists both changes: " + entries);
        shot(preview, "hi-live-deploy.png");
        clickButton(preview, "deploy.apply");
        waitFor("the refusal in the preview", () -> find(preview, javax.swing.JLabel.class, "deploy.outcome").getText()
                .startsWith("Refused, nothing applied"));
        check(network().snapshot().node(ref("Extra")) == null, "nothing applied");
        clickButton(preview, "deploy.cancel");
        waitFor("the preview closed", () -> !preview.isShowing());

        edt(() -> {
            menuItem("live.discard").doClick();
            menuItem("live.collect").doClick();
            var editor = window.current().editor();
            editor.setParameters(GAIN, List.of(Parameter.named("expression", "6 * in0")));
            editor.addNode("main", NodeInfo.data("Extra", LIB + "DoubleData"));
            return null;
        });
        JDialog second = openPreview();
        clickButton(second, "deploy.apply");
        waitFor("the preview closed after applying", () -> !second.isShowing());
        NetworkInfo running = network().snapshot();
        check(running.node(ref("Extra")) != null && "6 * in0".equals(running.node(GAIN).parameter("expression")),
                "both changes applied together");
        waitFor("live again", () -> window.getTitle().contains("live: live-editor-test"));
    }

    private JDialog openPreview() throws Exception {
        SwingUtilities.invokeLater(() -> menuItem("live.deploy").doClick());
        return dialogTitled("Deploy to");
    }

    private JDialog dialogTitled(String start) throws Exception {
        AtomicReference<JDialog> found = new AtomicReference<>();
        waitFor("the dialog " + start + "…", () -> {
            for (Window w : Window.getWindows()) {
                if (w instanceof JDialog d && d.isShowing() && d.getTitle().startsWith(start)) {
                    found.set(d);
                    return true;
                }
            }
            return false;
        });
        robot.waitForIdle();
        return found.get();
    }

    @SuppressWarnings("unchecked")
    private static List<String> entries(JDialog preview) {
        JList<Object> list = find(preview, JList.class, "deploy.entries");
        List<String> texts = new java.util.ArrayList<>();
        for (int i = 0; i < list.getModel().getSize(); i++) {
            texts.add(list.getModel().getElementAt(i).toString());
        }
        return texts;
    }

    /** What the network built by itself is saved with the rest, and placed in the .fdg. */
    private void saveRunningNetwork() throws Exception {
        Path saved = Files.createTempDirectory("live-save").resolve("running.fdn");
        edt(() -> {
            window.live().followNow();
            window.current().saveAs(saved);
            return null;
        });
        NetworkInfo read = NetworkRepository.load(saved);
        check(read.node(ref("Wheel filter")) != null && read.node(ref("Extra")) != null, "the saved file has the built nodes");
        check(LayoutRepository.load(LayoutRepository.sideFileOf(saved)).node(ref("Wheel filter")) != null,
                "the saved layout places them");
    }

    private void lostNetwork() throws Exception {
        run.close();
        waitFor("the status bar says the network is gone", () -> window.status().message().startsWith("The running network is gone"));
        check(edt(() -> window.getTitle()).contains("offline"), "the title says offline");
        check(edt(() -> window.current().editor().network().node(ref("Wheel filter"))) != null, "the last state stays shown");
        check(edt(() -> window.live()) == null, "no session any more");
        shot("hi-live-offline.png");
    }

    // ---------------------------------------------------------------- helpers

    private void shot(String name) throws Exception {
        shot(window, name);
    }

    private void shot(javax.swing.RootPaneContainer w, String name) throws Exception {
        robot.waitForIdle();
        Thread.sleep(250);
        edt(() -> {
            WindowScreenshot.write(w, images.resolve(name));
            return null;
        });
    }

    private JMenuItem menuItem(String name) {
        for (int i = 0; i < window.getJMenuBar().getMenuCount(); i++) {
            JMenu menu = window.getJMenuBar().getMenu(i);
            for (Component c : menu.getMenuComponents()) {
                if (c instanceof JMenuItem item && name.equals(item.getName())) {
                    return item;
                }
            }
        }
        throw new AssertionError("no menu item " + name);
    }

    private void clickButton(Container root, String name) throws Exception {
        Point p = edt(() -> {
            AbstractButton b = find(root, AbstractButton.class, name);
            if (b == null) {
                throw new AssertionError("no button " + name + " showing");
            }
            Point origin = b.getLocationOnScreen();
            return new Point(origin.x + b.getWidth() / 2, origin.y + b.getHeight() / 2);
        });
        robot.mouseMove(p.x, p.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        robot.waitForIdle();
    }

    private static <T extends Component> T find(Container root, Class<T> type, String key) {
        return ShowingComponents.find(root, type, key);
    }

    private static <T> T edt(Callable<T> query) throws Exception {
        return LiveTestNetwork.edt(query);
    }

    private void waitFor(String what, BooleanSupplier condition) throws Exception {
        ShowingComponents.waitFor(window, what, condition);
    }

    private static void check(boolean holds, String what) {
        ShowingComponents.check(holds, what);
    }
}

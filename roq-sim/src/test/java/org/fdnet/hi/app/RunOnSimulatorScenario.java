package org.fdnet.hi.app;

import java.nio.file.Path;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JDialog;
import javax.swing.JRadioButton;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.fdnet.hi.live.LiveTestNetwork;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.logger.InProcessLogger;

/**
 * Live → Run Open Network… on the simulated RoQ, driven like a user on a real display (run in a child JVM by
 * {@link RunOnSimulatorGuiTest}): the editor opens {@code networks/roq-stand.fdn}, the dialog's "On the simulated
 * RoQ" is chosen with course {@code flat}, the editor attaches at once and shows the sensor Data "joint angles"
 * changing as RoQ stands up in MuJoCo; Stop ends the run, the editor goes offline and a real logger (embedded
 * PostgreSQL, named in the dialog) holds the run with its events committed. Lives in roq-sim's tests
 * (package {@code org.fdnet.hi.app}, for the editor's scenario helpers) because the simulator is roq-sim's and
 * fdnet-hi must not depend on it. Prints "SCENARIO PASSED" and exits 0, or what failed.
 */
public final class RunOnSimulatorScenario {
    private static final Path STAND = Path.of("..", "networks", "roq-stand.fdn");
    private static final NodeRef JOINT_ANGLES = new NodeRef("main", "joint angles");

    private RunOnSimulatorScenario() {
    }

    public static void main(String[] args) {
        ScenarioProcess.runAndExit(prefs -> {
            try (InProcessLogger logger = InProcessLogger.throwaway()) {
                runAndStop(HiApplication.start(STAND.toAbsolutePath().normalize(), new RecentFiles(prefs)), logger);
            }
        });
    }

    /** Run from the dialog on course flat, recorded by {@code logger}; see it live; Stop; its events committed. */
    private static void runAndStop(HiWindow window, InProcessLogger logger) throws Exception {
        SwingUtilities.invokeLater(RunFromEditorScenario.menuItem(window, "live.run")::doClick);
        waitFor(window, "the Run dialog", () -> RunFromEditorScenario.dialog() != null);
        LiveTestNetwork.edt(() -> {
            JDialog d = RunFromEditorScenario.dialog();
            ShowingComponents.find(d, JRadioButton.class, "run.simulated").doClick();
            ShowingComponents.find(d, JComboBox.class, "run.course").setSelectedItem("flat");
            ShowingComponents.find(d, JTextField.class, "run.logger").setText("127.0.0.1:" + logger.receiverPort());
            ShowingComponents.find(d, JButton.class, "OK").doClick();
            return null;
        });
        waitFor(window, "roq-stand running on the simulator and the editor attached to it",
                () -> window.live() != null && window.live().name().equals("roq-stand"));
        ShowingComponents.check(LiveTestNetwork.edt(() -> window.status().message().startsWith("Running roq-stand")),
                "the status says it runs");
        waitFor(window, "joint angles' live value drawn",
                () -> window.current().scene().liveValue(JOINT_ANGLES) != null);
        String first = LiveTestNetwork.edt(() -> window.current().scene().liveValue(JOINT_ANGLES));
        waitFor(window, "joint angles' live value changing as RoQ stands (first " + first + ")",
                () -> !first.equals(window.current().scene().liveValue(JOINT_ANGLES)));
        LiveTestNetwork.edt(() -> {
            RunFromEditorScenario.menuItem(window, "live.stop").doClick();
            return null;
        });
        waitFor(window, "the run stopped and the editor offline", () -> window.live() == null
                && RunFromEditorScenario.menuItem(window, "live.run").isEnabled()
                && !RunFromEditorScenario.menuItem(window, "live.stop").isEnabled());
        EventCache events = logger.logger().cache();
        waitFor(window, "every event the logger received of the run committed", () -> events.committedCount() > 0
                && events.committedCount() == events.received());
        ShowingComponents.check(logger.logger().store().loadRuns().stream()
                .anyMatch(r -> r.network().equals("roq-stand")), "the logger holds the run of roq-stand");
    }

    private static void waitFor(HiWindow window, String what, java.util.function.BooleanSupplier condition)
            throws Exception {
        ShowingComponents.waitFor(window, what, condition);
    }
}

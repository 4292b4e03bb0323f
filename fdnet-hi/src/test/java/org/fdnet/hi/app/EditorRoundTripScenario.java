package org.fdnet.hi.app;

import java.awt.Component;
import java.awt.Container;
import java.awt.Point;
import java.awt.Robot;
import java.awt.Window;
import java.awt.event.InputEvent;
import java.awt.event.KeyEvent;
import java.awt.geom.Point2D;
import java.awt.geom.Rectangle2D;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.atomic.AtomicReference;
import java.util.function.BooleanSupplier;
import javax.swing.AbstractButton;
import javax.swing.JDialog;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.LayoutRepository;
import org.fdnet.netinfo.xml.NetworkRepository;

/**
 * The editor driven like a user on a real display (run in a child JVM by {@link EditorWindowGuiTest}):
 * open roq-motion.fdn, see it laid out, select and drag with the mouse, delete with the keyboard and undo,
 * edit a node's host in the text fields, merge two nodes through the dialog, undo the merge, save with
 * Ctrl-S, reopen, and compare. Prints "SCENARIO PASSED" and exits 0, or prints what failed and exits 1.
 */
public final class EditorRoundTripScenario {
    private static final NodeRef JUDGE = new NodeRef("Integration", "judge");
    private static final NodeRef BALANCE = new NodeRef("Balance", "balance candidate");
    private static final NodeRef WALK = new NodeRef("Walk", "walk candidate");
    private static final NodeRef JUDGMENT = new NodeRef("Integration", "judgment");
    private static final NodeRef TOO_STEEP = new NodeRef("Integration", "too steep");

    private final HiWindow window;
    private final Robot robot;

    private EditorRoundTripScenario(HiWindow window) throws Exception {
        this.window = window;
        this.robot = new Robot();
        robot.setAutoDelay(30);
    }

    public static void main(String[] args) throws Exception {
        Path file = Path.of(args[0]);
        ScenarioProcess.runAndExit(prefs -> {
            HiWindow window = HiApplication.start(file, new RecentFiles(prefs));
            new EditorRoundTripScenario(window).run(file);
        });
    }

    private void run(Path file) throws Exception {
        NetworkInfo original = NetworkRepository.load(file);
        waitFor("the window is shown", () -> window.isShowing() && window.canvas().getWidth() > 0);
        robot.waitForIdle();
        GraphScene scene = edt(() -> window.current().scene());
        check(edt(() -> scene.visibleNodes().stream().allMatch(r -> scene.bounds(r) != null)), "every node has a place");

        // Graphic view: click selects and fills the information panel; drag moves the node.
        click(JUDGE, 0);
        waitFor("judge selected", () -> scene.selection().equals(java.util.Set.of(JUDGE)));
        check(edt(() -> field("info.class").getText()).equals(original.node(JUDGE).className()), "the panel shows judge's class");
        Rectangle2D before = edt(() -> scene.bounds(JUDGE));
        drag(JUDGE, 80, 40);
        Rectangle2D after = edt(() -> scene.bounds(JUDGE));
        check(after.getX() > before.getX() + 20 && after.getY() > before.getY() + 10, "dragging moved judge: " + before + " -> " + after);

        // One click hides a module, another shows it; Ctrl-F finds a node by class and selects it.
        clickButton("module.Walk");
        waitFor("Walk hidden", () -> !scene.visible("Walk") && scene.visibleNodes().stream().noneMatch(r -> r.module().equals("Walk")));
        clickButton("module.Walk");
        waitFor("Walk shown", () -> scene.visible("Walk"));
        click(JUDGE, 0);
        key(KeyEvent.VK_F, InputEvent.CTRL_DOWN_MASK);
        waitFor("the search field has the focus", () -> field("search.field").isFocusOwner());
        robot.keyPress(KeyEvent.VK_T);
        robot.keyRelease(KeyEvent.VK_T);
        for (char c : "hreshold\n".toCharArray()) {
            int code = c == '\n' ? KeyEvent.VK_ENTER : KeyEvent.getExtendedKeyCodeForChar(c);
            robot.keyPress(code);
            robot.keyRelease(code);
        }
        waitFor("Ctrl-F found judge terrain", () -> scene.selection().equals(java.util.Set.of(new NodeRef("Integration", "judge terrain"))));

        // A rubber band from empty space selects the nodes it touches (after Ctrl-0 fits the network).
        key(KeyEvent.VK_0, InputEvent.CTRL_DOWN_MASK);
        Point corner = edt(() -> {
            Rectangle2D e = scene.extent();
            Point2D p = window.canvas().transform().transform(new Point2D.Double(e.getMaxX() + 5, e.getMaxY() + 5), null);
            Point origin = window.canvas().getLocationOnScreen();
            return new Point(origin.x + (int) p.getX(), origin.y + (int) p.getY());
        });
        Point walkCentre = onScreen(new NodeRef("Walk", "walk"));
        robot.mouseMove(corner.x, corner.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        for (int i = 1; i <= 10; i++) {
            robot.mouseMove(corner.x + (walkCentre.x - corner.x) * i / 10, corner.y + (walkCentre.y - corner.y) * i / 10);
        }
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        robot.waitForIdle();
        waitFor("the rubber band selected walk and walk candidate", () -> scene.selection().contains(WALK)
                && scene.selection().contains(new NodeRef("Walk", "walk")));

        // Graphic view: Delete removes the selected node and its connections; Ctrl-Z gives them back.
        click(WALK, 0);
        key(KeyEvent.VK_DELETE, 0);
        waitFor("walk candidate deleted", () -> window.current().editor().network().node(WALK) == null);
        key(KeyEvent.VK_Z, InputEvent.CTRL_DOWN_MASK);
        waitFor("walk candidate back", () -> window.current().editor().network().node(WALK) != null);
        check(edt(() -> window.current().editor().network().equals(original)), "undoing the delete gives the network back");

        // Text view: double-click judge opens the thesis's Advanced Module frame with judge loaded ("Update");
        // its host is changed there, then a parameter value in the information panel.
        doubleClick(JUDGE);
        JDialog frame = dialog();
        check(edt(frame::getTitle).equals("Module Integration"), "double-click opens judge's module: " + edt(frame::getTitle));
        waitFor("judge loaded in the frame", () -> find(frame, AbstractButton.class, "Update") != null);
        SwingUtilities.invokeAndWait(() -> {
            fieldAfter(frame, "Host :").setText("robot-2");
            find(frame, AbstractButton.class, "Update").doClick();
        });
        waitFor("judge's host changed", () -> "robot-2".equals(window.current().editor().network().node(JUDGE).host()));
        SwingUtilities.invokeAndWait(frame::dispose);
        click(JUDGE, 0);
        SwingUtilities.invokeAndWait(() -> {
            javax.swing.JTable table = find(window, javax.swing.JTable.class, "info.parameters");
            table.setValueAt("in1 * (in0 ? 0.3 : 1.0)", 0, 2);
            button("info.applyNode").doClick();
        });
        waitFor("judge's expression changed", () -> window.current().editor().network().node(JUDGE).parameter("expression").contains("0.3"));
        NetworkInfo edited = edt(() -> window.current().editor().network().copy());

        // A Data and a Relation of different modules: nothing can make them one node, so Ctrl-M offers nothing
        // (no dialog); the status bar says why; nothing changes, nothing to undo.
        click(BALANCE, 0);
        click(JUDGE, InputEvent.CTRL_DOWN_MASK);
        waitFor("two nodes selected", () -> scene.selection().size() == 2);
        Rectangle2D judgePlace = edt(() -> scene.bounds(JUDGE));
        String undoBefore = edt(() -> window.current().editor().undoLabel());
        key(KeyEvent.VK_M, InputEvent.CTRL_DOWN_MASK);
        waitFor("the reason in the status bar", () -> window.status().message().startsWith("Cannot make " + BALANCE));
        check(edt(() -> window.status().message()).contains("replace works within one module"), "it says why: "
                + edt(() -> window.status().message()));
        check(edt(() -> java.util.Arrays.stream(Window.getWindows()).noneMatch(w -> w instanceof JDialog && w.isShowing())),
                "no Merge/Replace question is asked");
        check(edt(() -> window.current().editor().network().equals(edited)), "a refused merge changes nothing");
        check(edt(() -> scene.bounds(JUDGE)).equals(judgePlace), "a refused merge moves nothing");
        check(java.util.Objects.equals(edt(() -> window.current().editor().undoLabel()), undoBefore), "a refusal is not a step");

        // Merge two nodes of one module through the thesis's Merge/Replace dialog (click the node that stays,
        // Ctrl-click the other, Ctrl-M, Merge, OK), then undo it.
        click(JUDGMENT, 0);
        click(TOO_STEEP, InputEvent.CTRL_DOWN_MASK);
        waitFor("two nodes selected", () -> scene.selection().size() == 2);
        key(KeyEvent.VK_M, InputEvent.CTRL_DOWN_MASK);
        JDialog mergeQuestion = dialog();
        SwingUtilities.invokeAndWait(() -> {
            find(mergeQuestion, AbstractButton.class, "Merge").doClick();
            find(mergeQuestion, AbstractButton.class, "OK").doClick();
        });
        waitFor("merged", () -> window.current().editor().network().node(TOO_STEEP) == null);
        check(edt(() -> window.current().editor().network().connectionsOf(TOO_STEEP).isEmpty()), "no connection names the merged node");
        check(edt(() -> window.current().editor().network().connectionsOf(JUDGMENT).size()
                > edited.connectionsOf(JUDGMENT).size()), "the node that stays has the other's connections");
        key(KeyEvent.VK_Z, InputEvent.CTRL_DOWN_MASK);
        waitFor("merge undone", () -> window.current().editor().network().node(TOO_STEEP) != null);
        check(edt(() -> window.current().editor().network().equals(edited)), "undoing the merge gives the edited network back");

        // Add a Data and a Relation (Edit menu), select the Data then Ctrl-click the Relation, Ctrl-K: a Reader.
        NodeRef speed = new NodeRef("main", "speed target");
        NodeRef planner = new NodeRef("main", "speed planner");
        addNode("Add Data…", speed.node());
        waitFor("the Data added and selected", () -> window.current().editor().network().node(speed) != null
                && scene.selection().equals(java.util.Set.of(speed)));
        addNode("Add Relation…", planner.node());
        waitFor("the Relation added and selected", () -> window.current().editor().network().node(planner) != null
                && scene.selection().equals(java.util.Set.of(planner)));
        check(edt(() -> window.current().editor().network().node(speed).kind() == org.fdnet.netinfo.NodeKind.DATA
                && window.current().editor().network().node(planner).kind() == org.fdnet.netinfo.NodeKind.RELATION),
                "a Data and a Relation");
        key(KeyEvent.VK_0, InputEvent.CTRL_DOWN_MASK);
        click(speed, 0);
        click(planner, InputEvent.CTRL_DOWN_MASK);
        waitFor("both new nodes selected", () -> scene.selection().size() == 2);
        key(KeyEvent.VK_K, InputEvent.CTRL_DOWN_MASK);
        waitFor("Ctrl-K connected them with a Reader", () -> window.current().editor().network().connectionsOf(speed).stream()
                .anyMatch(c -> c.connection().kind() == org.fdnet.netinfo.ConnectionKind.READER
                        && c.connection().relation().equals(planner)));
        check(edt(() -> scene.selectedConnection() != null), "the new Reader is selected on the drawing");
        for (int i = 0; i < 3; i++) {
            key(KeyEvent.VK_Z, InputEvent.CTRL_DOWN_MASK);
        }
        waitFor("connect, add Relation and add Data undone", () -> window.current().editor().network().equals(edited));

        // The title marks unsaved edits; Ctrl-N asks first, and Cancel keeps everything.
        check(edt(() -> window.getTitle().startsWith("*")), "the title marks unsaved edits: " + edt(window::getTitle));
        key(KeyEvent.VK_N, InputEvent.CTRL_DOWN_MASK);
        JDialog unsaved = dialog();
        check(edt(unsaved::getTitle).equals("Unsaved changes"), "Ctrl-N asks before losing edits");
        SwingUtilities.invokeAndWait(() -> find(unsaved, AbstractButton.class, "Cancel").doClick());
        waitFor("the dialog closed", () -> !unsaved.isShowing());
        check(edt(() -> window.current().editor().network().equals(edited) && window.current().unsaved()), "Cancel keeps the edits");
        SwingUtilities.invokeAndWait(() -> window.canvas().requestFocus());

        // Save with Ctrl-S; reopen the file and find the same network and the same layout.
        key(KeyEvent.VK_S, InputEvent.CTRL_DOWN_MASK);
        waitFor("saved", () -> !window.current().unsaved());
        check(edt(() -> !window.getTitle().startsWith("*")), "the title is clean after saving");
        NetworkLayout savedLayout = edt(() -> window.current().savedLayout());
        SwingUtilities.invokeAndWait(() -> window.open(file));
        check(edt(() -> window.current().editor().network().equals(edited)), "the reopened network is the edited one");
        check(NetworkRepository.load(file).equals(edited), "the file holds the edited network");
        check(LayoutRepository.load(LayoutRepository.sideFileOf(file)).equals(savedLayout), "the .fdg holds the layout as shown");
        check(edt(() -> window.current().scene().bounds(JUDGE)).equals(after), "judge is where it was dragged");
        SwingUtilities.invokeAndWait(window::dispose);
    }

    // ---------------------------------------------------------------- driving

    /** Edit → {@code item} (Add Data… / Add Relation…): names the new node in main and presses OK. */
    private void addNode(String item, String name) throws Exception {
        javax.swing.JMenuItem menuItem = edt(() -> {
            javax.swing.JMenu edit = find(window.getJMenuBar(), javax.swing.JMenu.class, "menu.edit");
            for (int i = 0; i < edit.getItemCount(); i++) {
                if (edit.getItem(i) != null && item.equals(edit.getItem(i).getText())) {
                    return edit.getItem(i);
                }
            }
            throw new AssertionError("no Edit menu item " + item);
        });
        SwingUtilities.invokeLater(menuItem::doClick); // its dialog is modal: do not wait for it here
        JDialog form = dialog();
        SwingUtilities.invokeAndWait(() -> {
            find(form, javax.swing.JComboBox.class, null).setSelectedItem("main");
            fieldAfter(form, "Name").setText(name);
            find(form, AbstractButton.class, "OK").doClick();
        });
        waitFor("the form closed", () -> !form.isShowing());
    }

    /** The modal dialog now showing. */
    private JDialog dialog() throws Exception {
        AtomicReference<JDialog> dialog = new AtomicReference<>();
        waitFor("a dialog", () -> {
            for (Window w : Window.getWindows()) {
                if (w instanceof JDialog d && d.isShowing()) {
                    dialog.set(d);
                    return true;
                }
            }
            return false;
        });
        return dialog.get();
    }

    private Point onScreen(NodeRef ref) throws Exception {
        return edt(() -> {
            Rectangle2D b = window.current().scene().bounds(ref);
            Point2D p = window.canvas().transform().transform(new Point2D.Double(b.getCenterX(), b.getCenterY()), null);
            Point origin = window.canvas().getLocationOnScreen();
            return new Point(origin.x + (int) p.getX(), origin.y + (int) p.getY());
        });
    }

    private void click(NodeRef ref, int modifiers) throws Exception {
        Point p = onScreen(ref);
        robot.mouseMove(p.x, p.y);
        press(modifiers, true);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        press(modifiers, false);
        robot.waitForIdle();
    }

    private void doubleClick(NodeRef ref) throws Exception {
        Point p = onScreen(ref);
        robot.mouseMove(p.x, p.y);
        for (int i = 0; i < 2; i++) {
            robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
            robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        }
        robot.waitForIdle();
    }

    /** The text field placed right after the label {@code label} in the same panel. */
    private static JTextField fieldAfter(Container root, String label) {
        for (Component c : root.getComponents()) {
            if (c instanceof javax.swing.JLabel l && label.equals(l.getText())) {
                Component[] siblings = c.getParent().getComponents();
                for (int i = 0; i < siblings.length - 1; i++) {
                    if (siblings[i] == c && siblings[i + 1] instanceof JTextField f) {
                        return f;
                    }
                }
            }
            if (c instanceof Container inner) {
                JTextField found = fieldAfter(inner, label);
                if (found != null) {
                    return found;
                }
            }
        }
        return null;
    }

    private void drag(NodeRef ref, int dx, int dy) throws Exception {
        Point p = onScreen(ref);
        robot.mouseMove(p.x, p.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        for (int i = 1; i <= 10; i++) {
            robot.mouseMove(p.x + dx * i / 10, p.y + dy * i / 10);
        }
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        robot.waitForIdle();
    }

    private void key(int code, int modifiers) {
        press(modifiers, true);
        robot.keyPress(code);
        robot.keyRelease(code);
        press(modifiers, false);
        robot.waitForIdle();
    }

    private void press(int modifiers, boolean down) {
        if ((modifiers & InputEvent.CTRL_DOWN_MASK) != 0) {
            if (down) {
                robot.keyPress(KeyEvent.VK_CONTROL);
            } else {
                robot.keyRelease(KeyEvent.VK_CONTROL);
            }
        }
    }

    private void clickButton(String name) throws Exception {
        Point p = edt(() -> {
            AbstractButton b = button(name);
            Point origin = b.getLocationOnScreen();
            return new Point(origin.x + b.getWidth() / 2, origin.y + b.getHeight() / 2);
        });
        robot.mouseMove(p.x, p.y);
        robot.mousePress(InputEvent.BUTTON1_DOWN_MASK);
        robot.mouseRelease(InputEvent.BUTTON1_DOWN_MASK);
        robot.waitForIdle();
    }

    private JTextField field(String name) {
        return find(window, JTextField.class, name);
    }

    private AbstractButton button(String name) {
        return find(window, AbstractButton.class, name);
    }

    private static <T extends Component> T find(Container root, Class<T> type, String key) {
        return ShowingComponents.find(root, type, key);
    }

    private static <T> T edt(Callable<T> query) throws Exception {
        return org.fdnet.hi.live.LiveTestNetwork.edt(query);
    }

    private void waitFor(String what, BooleanSupplier condition) throws Exception {
        ShowingComponents.waitFor(window, what, condition);
    }

    private static void check(boolean holds, String what) {
        ShowingComponents.check(holds, what);
    }
}

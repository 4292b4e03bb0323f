package org.fdnet.hi.text;

import java.awt.Component;
import java.awt.Container;
import java.awt.Window;
import java.awt.event.KeyEvent;
import java.lang.reflect.InvocationTargetException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;

import javax.swing.AbstractButton;
import javax.swing.JComboBox;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;

import com.formdev.flatlaf.FlatLightLaf;
import org.fdnet.hi.merge.MergeReplaceDialog;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.ModuleCounts;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * Runs in a child JVM on a real X display ({@link TextFramesDisplayTest}): opens the three text frames on the
 * sample network, types into them key by key, clicks their buttons, and checks the network and the other
 * frames after each step. Prints "STEP ..." lines; exits 1 with the reason on the first failed check.
 * Argument: the folder for the frames' PNG screenshots.
 */
public final class TextFramesScenario {
    private final NetworkInfo network = SampleNetwork.create();
    private final PlainNetworkEditor editor = new PlainNetworkEditor(network);
    private NetworkFrame networkFrame;
    private BasicModuleFrame basic;
    private AdvancedModuleFrame advanced;

    public static void main(String[] args) throws Exception {
        try {
            new TextFramesScenario().run(Path.of(args[0]));
            System.out.println("STEP all passed");
            System.exit(0);
        } catch (AssertionError | Exception e) {
            System.out.println("FAILED " + e);
            for (StackTraceElement s : e.getStackTrace()) {
                System.out.println("    at " + s); // the parent test shows this output when the scenario fails
            }
            System.exit(1);
        }
    }

    private void run(Path shots) throws Exception {
        onEdt(() -> {
            FlatLightLaf.setup();
            networkFrame = NetworkFrame.open(null, editor);
            basic = BasicModuleFrame.open(networkFrame, editor, "main");
            advanced = AdvancedModuleFrame.open(networkFrame, editor, "main");
        });
        step("frames open");

        // typing an existing node's name loads it and Save turns into Update
        type(advanced.nodeName, "Spe");
        onEdt(() -> check(advanced.saveNode.getText().equals("Save"), "Save while 'Spe' names no node"));
        type(advanced.nodeName, "ed");
        onEdt(() -> {
            check(advanced.saveNode.getText().equals("Update"), "button says Update, not " + advanced.saveNode.getText());
            check(advanced.host.getText().equals("roq"), "host loaded, was " + advanced.host.getText());
            check(advanced.className.getText().equals("fdnet.SpeedData"), "class loaded");
            check(advanced.paramRows.getRowCount() == 2, "two parameters loaded");
            check("long".equals(advanced.paramRows.getValueAt(0, 2)), "first parameter typed long");
            check(advanced.deleteNode.isEnabled(), "Delete enabled for an existing node");
        });
        step("existing name loads node and Update");
        onEdt(() -> FrameScreenshot.write(advanced, shots.resolve("text-advanced-module.png")));

        // a typed parameter that does not fit its type is refused with a message; a good one is added
        type(advanced.paramName, "limit");
        onEdt(() -> advanced.paramType.setSelectedItem("double"));
        type(advanced.paramValue, "fast");
        onEdt(() -> {
            advanced.addParam.doClick();
            check(advanced.status.getText().contains("'fast' is not a number"), "refusal shown: " + advanced.status.getText());
            check(advanced.paramRows.getRowCount() == 2, "refused parameter not added");
            advanced.paramValue.setText("");
        });
        type(advanced.paramValue, "2.5");
        onEdt(() -> {
            advanced.addParam.doClick();
            check(advanced.paramRows.getRowCount() == 3, "parameter added to the table");
            advanced.saveNode.doClick();
            check(network.node(SampleNetwork.SPEED).parameter("limit").equals("2.5"), "Update kept the new parameter");
        });
        step("typed parameter refused then added and updated");

        // a new node: fields typed, Save adds it, the other frames count it
        onEdt(() -> advanced.nodeName.setText(""));
        type(advanced.nodeName, "Brake");
        onEdt(() -> {
            check(advanced.saveNode.getText().equals("Save"), "Save for a new name");
            check(advanced.className.getText().equals("fdnet.SpeedData"), "a new name keeps the form (copy a node)");
            advanced.className.setText("");
            advanced.paramTable.setRowSelectionInterval(0, 0);
            advanced.deleteParam.doClick();
            check(advanced.paramRows.getRowCount() == 2, "a parameter deleted from the form");
        });
        type(advanced.className, "fdnet.Brake");
        onEdt(() -> {
            advanced.saveNode.doClick();
            check(network.node(new NodeRef("main", "Brake")) != null, "Brake added");
            check(advanced.saveNode.getText().equals("Update"), "after Save the button says Update");
            check(Integer.valueOf(3).equals(networkFrame.rows.getValueAt(0, 2)), "Network frame counts 3 Datas in main");
            check(basic.nodeRows.contains("Data Brake"), "Basic frame lists Brake");
        });
        step("new node saved and counted");

        // the class's declared parameters are listed with their descriptions; one chosen is offered for Add
        onEdt(() -> {
            advanced.nodeKind.setSelectedItem(NodeKind.RELATION);
            advanced.path.setText(""); // a built-in class
            advanced.className.setText("");
        });
        type(advanced.className, "Threshold");
        onEdt(() -> {
            int listed = advanced.declared.rows.getRowCount();
            check(listed == 6, "Threshold's 6 declared parameters listed, not " + listed + ": " + advanced.declared.note.getText());
            check("high".equals(advanced.declared.rows.getValueAt(0, 0)), "the class's own first");
            check(String.valueOf(advanced.declared.rows.getValueAt(0, 4)).contains("rises above"), "with a description");
            advanced.declared.table.setRowSelectionInterval(2, 2);
            check(advanced.paramName.getText().equals("absolute"), "chosen parameter offered: " + advanced.paramName.getText());
            check("boolean".equals(advanced.paramType.getSelectedItem()), "with its type");
            check(advanced.paramValue.getText().equals("false"), "and its default value");
            advanced.paramName.setText("");
            advanced.paramValue.setText("");
            advanced.className.setText("fdnet.Brake");
            advanced.path.setText("/opt/nodes");
            advanced.nodeKind.setSelectedItem(NodeKind.DATA);
            check(advanced.declared.note.getText().contains("class 'fdnet.Brake'"), "why Brake's are not listed: "
                    + advanced.declared.note.getText());
        });
        step("declared parameters listed and offered");

        // connection ends offer only existing nodes
        onEdt(() -> {
            advanced.tabs.setSelectedIndex(1);
            List<String> datas = items(advanced.dataEnd);
            check(datas.equals(List.of("Speed", "Command", "Brake", "Arm/Angle")), "Data choices " + datas);
            List<String> relations = items(advanced.relationEnd);
            check(relations.equals(List.of("Control", "Arm/Servo")), "Relation choices " + relations);
            check(!advanced.dataEnd.isEditable(), "a Data end cannot be typed freely");
            check(!advanced.addConnection.isEnabled(), "Add disabled before both ends are chosen");
            advanced.connectionKind.setSelectedItem(ConnectionKind.READER);
            advanced.dataEnd.setSelectedItem("Brake");
            advanced.relationEnd.setSelectedItem("Control");
            check(advanced.addConnection.isEnabled(), "Add enabled once both ends are chosen");
            advanced.addConnection.doClick();
            check(network.main().connections().contains(ConnectionInfo.reader(new NodeRef("main", "Brake"),
                    SampleNetwork.CONTROL)), "Reader Brake -> Control added");
            check(advanced.connectionRows.contains("Reader Brake → Control"), "connection listed");
        });
        onEdt(() -> FrameScreenshot.write(advanced, shots.resolve("text-advanced-connections.png")));
        step("connection fields offer only existing nodes");

        // deleting a node deletes its connections, here and in module Arm
        onEdt(() -> {
            advanced.tabs.setSelectedIndex(0);
            advanced.nodeName.setText("");
        });
        type(advanced.nodeName, "Speed");
        onEdt(() -> {
            advanced.deleteNode.doClick();
            check(network.node(SampleNetwork.SPEED) == null, "Speed deleted");
            check(network.module("Arm").connections().size() == 1, "Arm's Reader of Speed deleted with it");
            check(network.main().connections().size() == 2, "main keeps Writer Control->Command and Reader Brake->Control");
            check(advanced.saveNode.getText().equals("Save"), "the typed name is free again: Save");
            check(!items(advanced.dataEnd).contains("Speed"), "Speed no longer offered as a Data end");
            check(networkFrame.rows.getValueAt(1, 4).equals(1), "Network frame: Arm has 1 Reader left");
        });
        step("deleting a node deletes its connections");

        // the frames follow a change made elsewhere (as the graphic editor or undo would)
        onEdt(() -> {
            editor.addModule("Leg", true);
            check(networkFrame.moduleCount.getText().endsWith("3"), "Network frame counts 3 modules");
            ModuleCounts t = network.totalCounts();
            check(networkFrame.total.getText().contains(t.datas() + " Datas"), "total follows");
            editor.renameModule("Leg", "LeftLeg");
            check(networkFrame.rows.getValueAt(2, 0).equals("LeftLeg"), "rename shown");
        });
        step("frames refresh on changes from elsewhere");

        // Network frame: typing an existing module name turns New into Edit; New adds a module
        type(networkFrame.moduleName, "Arm");
        onEdt(() -> check(networkFrame.save.getText().equals("Edit"), "Edit for an existing module"));
        onEdt(() -> networkFrame.moduleName.setText(""));
        type(networkFrame.moduleName, "Head");
        onEdt(() -> {
            check(networkFrame.save.getText().equals("New"), "New for a new module name");
            networkFrame.loadAtStart.doClick();
            networkFrame.save.doClick();
            check(network.module("Head") != null && !network.module("Head").loadAtStart(), "Head added, not loaded at start");
        });
        onEdt(() -> FrameScreenshot.write(networkFrame, shots.resolve("text-network.png")));
        step("module added from the Network frame");

        // Network frame: type a new network name and press Rename
        onEdt(() -> networkFrame.networkName.setText(""));
        type(networkFrame.networkName, "rover");
        onEdt(() -> {
            networkFrame.rename.doClick();
            check("rover".equals(network.name()), "network renamed: " + networkFrame.status.getText());
            check(networkFrame.status.getText().equals("renamed the network to rover"), "the frame says so");
            check(networkFrame.networkName.getText().equals("rover"), "the frame shows the new name");
        });
        step("network renamed from the Network frame");

        // Basic module frame: rename the module; delete a connection
        onEdt(() -> basic.dispose());
        AtomicReference<BasicModuleFrame> arm = new AtomicReference<>();
        onEdt(() -> arm.set(BasicModuleFrame.open(networkFrame, editor, "Arm")));
        onEdt(() -> arm.get().moduleName.setText(""));
        type(arm.get().moduleName, "RightArm");
        onEdt(() -> {
            arm.get().save.doClick();
            check(network.module("RightArm") != null, "module renamed from the Basic frame: " + arm.get().status.getText());
            check(arm.get().getTitle().equals("Module RightArm"), "title follows");
            arm.get().connectionList.setSelectedIndex(0);
            arm.get().deleteConnection.doClick();
            check(network.module("RightArm").connections().isEmpty(), "connection deleted");
            check(arm.get().numbers.getText().startsWith("2 nodes"), "numbers: " + arm.get().numbers.getText());
        });
        onEdt(() -> FrameScreenshot.write(arm.get(), shots.resolve("text-basic-module.png")));
        step("basic frame renames module and deletes connection");

        // renaming a node to a name the module uses asks Merge or Replace; Replace: Brake takes Command's place
        onEdt(() -> advanced.nodeName.setText(""));
        type(advanced.nodeName, "Brake");
        type(advanced.newName, "Command");
        SwingUtilities.invokeLater(advanced.renameNode::doClick); // the dialog is modal: click from a later event
        Window dialog = awaitWindow(MergeReplaceDialog.class);
        onEdt(() -> {
            button(dialog, "Replace").doClick();
            button(dialog, "OK").doClick();
        });
        onEdt(() -> {
            check(!dialog.isShowing(), "dialog closed after OK");
            check(network.node(new NodeRef("main", "Brake")) == null, "Brake's old name is gone");
            check(network.node(SampleNetwork.COMMAND).className().equals("fdnet.Brake"), "Command is Brake's node now: "
                    + network.node(SampleNetwork.COMMAND));
            check(network.main().connections().equals(List.of(ConnectionInfo.reader(SampleNetwork.COMMAND,
                    SampleNetwork.CONTROL))), "only Brake's connection remains, now to Command: " + network.main().connections());
            check(advanced.nodeName.getText().equals("Command"), "the form shows the node under its new name");
            check(advanced.saveNode.getText().equals("Update"), "and offers Update");
            check(advanced.className.getText().equals("fdnet.Brake"), "with the replacement's class");
        });
        step("rename to a used name asks merge or replace");

        onEdt(() -> {
            arm.get().dispose();
            advanced.dispose();
            networkFrame.dispose();
        });
    }

    /** Waits (bounded) until a window of {@code type} shows; the modal dialog opens from a later event. */
    private static Window awaitWindow(Class<? extends Window> type) throws Exception {
        AtomicReference<Window> found = new AtomicReference<>();
        long deadline = System.nanoTime() + 30_000_000_000L;
        while (found.get() == null && System.nanoTime() < deadline) {
            onEdt(() -> {
                for (Window w : Window.getWindows()) {
                    if (type.isInstance(w) && w.isShowing()) {
                        found.set(w);
                    }
                }
            });
            Thread.sleep(50);
        }
        check(found.get() != null, type.getSimpleName() + " opened");
        return found.get();
    }

    /** The button of {@code window} whose text is {@code text}, as a user finds it. */
    private static AbstractButton button(Container container, String text) {
        for (Component c : container.getComponents()) {
            if (c instanceof AbstractButton b && text.equals(b.getText())) {
                return b;
            }
            if (c instanceof Container inner) {
                AbstractButton b = button(inner, text);
                if (b != null) {
                    return b;
                }
            }
        }
        return null;
    }

    private static List<String> items(JComboBox<String> combo) {
        List<String> list = new ArrayList<>();
        for (int i = 0; i < combo.getItemCount(); i++) {
            list.add(combo.getItemAt(i));
        }
        return list;
    }

    /** Types {@code text} into {@code field} one key at a time, as KEY_TYPED events through its keymap. */
    private static void type(JTextField field, String text) throws Exception {
        for (char c : text.toCharArray()) {
            onEdt(() -> {
                field.setCaretPosition(field.getText().length());
                field.dispatchEvent(new KeyEvent(field, KeyEvent.KEY_TYPED, System.currentTimeMillis(), 0,
                        KeyEvent.VK_UNDEFINED, c));
            });
        }
    }

    private static void check(boolean ok, String what) {
        if (!ok) {
            throw new AssertionError(what);
        }
    }

    private static void step(String what) {
        System.out.println("STEP " + what);
    }

    interface EdtAction {
        void run() throws Exception;
    }

    static void onEdt(EdtAction action) throws InterruptedException, InvocationTargetException {
        AtomicReference<Throwable> failure = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            try {
                action.run();
            } catch (Throwable t) {
                failure.set(t);
            }
        });
        if (failure.get() instanceof AssertionError a) {
            throw a;
        }
        if (failure.get() != null) {
            throw new IllegalStateException(failure.get());
        }
    }
}

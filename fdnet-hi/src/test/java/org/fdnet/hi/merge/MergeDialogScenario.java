package org.fdnet.hi.merge;

import java.awt.Window;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;

import javax.swing.SwingUtilities;

import com.formdev.flatlaf.FlatLightLaf;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.hi.text.FrameScreenshot;
import org.fdnet.hi.text.PlainNetworkEditor;
import org.fdnet.hi.text.SampleNetwork;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.MergePolicy;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;

/**
 * Runs in a child JVM on a real X display ({@link MergeDialogDisplayTest}): renames main/SpeedV2 to the used
 * name "Speed" through {@link MergeReplaceDialog#renameOrAsk}, answers the modal dialog as a user would
 * (Replace, or Merge with each parameter policy), and checks the network. Prints "STEP ..." lines; exits 1 with
 * the reason on the first failed check. Argument: the folder for the dialog's PNG screenshot.
 */
public final class MergeDialogScenario {
    private static final NodeRef SPEED_V2 = new NodeRef("main", "SpeedV2");
    private static final NodeRef LOGGER = new NodeRef("main", "Logger");

    public static void main(String[] args) throws Exception {
        try {
            run(Path.of(args[0]));
            System.out.println("STEP all passed");
            System.exit(0);
        } catch (AssertionError | Exception e) {
            System.out.println("FAILED " + e);
            for (StackTraceElement s : e.getStackTrace()) {
                System.out.println("    at " + s);
            }
            System.exit(1);
        }
    }

    private static NetworkInfo network() {
        NetworkInfo n = SampleNetwork.create();
        n.addNode("main", NodeInfo.data("SpeedV2", "fdnet.SpeedV2", Parameter.named("gain", "9"), Parameter.of("slow")));
        n.addNode("main", NodeInfo.relation("Logger", "fdnet.Logger"));
        n.addConnection("main", ConnectionInfo.reader(SPEED_V2, LOGGER));
        return n;
    }

    private static void run(Path shots) throws Exception {
        SwingUtilities.invokeAndWait(FlatLightLaf::setup);

        NetworkInfo replaced = network();
        EditResult r = answer(replaced, SPEED_V2, dialog -> dialog.replaceButton().doClick(), null);
        check(r != null && r.accepted(), "replace accepted");
        check(replaced.node(SampleNetwork.SPEED).className().equals("fdnet.SpeedV2"), "Speed is now SpeedV2's node");
        check(replaced.node(SPEED_V2) == null, "SpeedV2's old name is gone");
        check(replaced.connectionsOf(SampleNetwork.SPEED).size() == 1, "only the replacement's connection remains");
        step("replace");

        String[] expected = {"3 fast", "9 slow", "3 fast slow"};
        for (MergePolicy policy : MergePolicy.values()) {
            NetworkInfo merged = network();
            Path shot = policy == MergePolicy.BOTH ? shots.resolve("merge-replace-dialog.png") : null;
            EditResult m = answer(merged, SPEED_V2, dialog -> {
                dialog.mergeButton().doClick();
                check(dialog.policyButton(policy).isEnabled(), "policies enabled once Merge is chosen");
                dialog.policyButton(policy).doClick();
            }, shot);
            check(m != null && m.accepted(), "merge " + policy + " accepted");
            NodeInfo speed = merged.node(SampleNetwork.SPEED);
            String values = String.join(" ", speed.parameters().stream().map(Parameter::value).toList());
            check(values.equals(expected[policy.ordinal()]), "merge " + policy + " kept parameters " + values);
            check(speed.className().equals("fdnet.SpeedData"), "merge keeps the existing node's class");
            check(merged.connectionsOf(SampleNetwork.SPEED).size() == 3, "merge keeps the connections of both");
            step("merge " + policy);
        }

        NetworkInfo mixed = network();
        EditResult none = answer(mixed, LOGGER, dialog -> {
            check(!dialog.mergeButton().isEnabled(), "a Relation cannot merge with a Data: Merge disabled");
            dialog.dispose();
        }, null);
        check(none == null, "closing the dialog cancels");
        check(mixed.node(LOGGER) != null && mixed.node(SampleNetwork.SPEED) != null, "cancel changes nothing");
        step("merge refused between kinds, cancel changes nothing");
    }

    interface Answer {
        void on(MergeReplaceDialog dialog) throws Exception;
    }

    /** Renames {@code node} to "Speed" on the event thread, answers the dialog that opens, returns the result. */
    private static EditResult answer(NetworkInfo network, NodeRef node, Answer answer, Path shot) throws Exception {
        PlainNetworkEditor editor = new PlainNetworkEditor(network);
        AtomicReference<EditResult> result = new AtomicReference<>();
        AtomicReference<Boolean> done = new AtomicReference<>(false);
        SwingUtilities.invokeLater(() -> {
            result.set(MergeReplaceDialog.renameOrAsk(null, editor, node, "Speed"));
            done.set(true);
        });
        AtomicReference<MergeReplaceDialog> dialog = new AtomicReference<>();
        long deadline = System.nanoTime() + 30_000_000_000L;
        while (dialog.get() == null && System.nanoTime() < deadline) {
            SwingUtilities.invokeAndWait(() -> {
                for (Window w : Window.getWindows()) {
                    if (w instanceof MergeReplaceDialog d && d.isShowing()) {
                        dialog.set(d);
                    }
                }
            });
            Thread.sleep(50);
        }
        check(dialog.get() != null, "the Merge/Replace dialog opened for a used name");
        AtomicReference<Throwable> failure = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            try {
                answer.on(dialog.get());
                if (dialog.get().isShowing()) {
                    if (shot != null) {
                        FrameScreenshot.write(dialog.get(), shot);
                    }
                    dialog.get().okButton().doClick();
                }
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
        while (!done.get() && System.nanoTime() < deadline) {
            Thread.sleep(50);
        }
        check(done.get(), "renameOrAsk returned once the dialog closed");
        return result.get();
    }

    private static void check(boolean ok, String what) {
        if (!ok) {
            throw new AssertionError(what);
        }
    }

    private static void step(String what) {
        System.out.println("STEP " + what);
    }
}

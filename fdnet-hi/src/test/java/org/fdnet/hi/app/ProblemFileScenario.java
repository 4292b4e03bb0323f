package org.fdnet.hi.app;

import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.SwingUtilities;
import org.fdnet.netinfo.xml.Problem;

/**
 * A file with problems on a real display (run by {@link EditorWindowGuiTest}): it opens read-only with its
 * problem list, nothing can be edited or saved, and choosing each problem puts the caret on its line.
 */
public final class ProblemFileScenario {
    private ProblemFileScenario() {
    }

    public static void main(String[] args) throws Exception {
        ScenarioProcess.runAndExit(prefs -> {
            HiWindow window = HiApplication.start(Path.of(args[0]), new RecentFiles(prefs));
            AtomicReference<String> failure = new AtomicReference<>();
            SwingUtilities.invokeAndWait(() -> failure.set(check(window)));
            SwingUtilities.invokeAndWait(window::dispose);
            if (failure.get() != null) {
                throw new AssertionError(failure.get());
            }
        });
    }

    private static String check(HiWindow window) {
        ProblemView view = window.problems();
        if (view == null || window.current() != null) {
            return "the file did not open read-only with its problems";
        }
        if (!window.getTitle().contains("read-only")) {
            return "the title does not say read-only: " + window.getTitle();
        }
        if (window.getJMenuBar().getMenu(1).getItem(0).isEnabled() || window.getJMenuBar().getMenu(0).getItem(4).isEnabled()) {
            return "undo or save is enabled on a read-only file";
        }
        int n = view.problemList().getModel().getSize();
        if (n < 2) {
            return "expected at least two problems, got " + n;
        }
        for (int i = n - 1; i >= 0; i--) {
            Problem p = view.problemList().getModel().getElementAt(i);
            view.problemList().setSelectedIndex(i);
            if (view.caretLine() != p.line()) {
                return "choosing " + p + " put the caret on line " + view.caretLine();
            }
        }
        return null;
    }
}

package org.fdnet.hi.app;

import java.nio.file.Path;
import java.util.List;
import org.fdnet.testing.OnEdt;
import org.fdnet.testing.WindowVisibility;

/**
 * The editor on a real display at its default size with a network open (run by {@link EditorWindowGuiTest}):
 * every control a person uses is on screen, whole, and no label is cut ({@link WindowVisibility}).
 */
public final class EditorVisibilityScenario {
    private EditorVisibilityScenario() {
    }

    public static void main(String[] args) throws Exception {
        ScenarioProcess.runAndExit(prefs -> {
            HiWindow window = HiApplication.start(Path.of(args[0]), new RecentFiles(prefs));
            long deadline = System.nanoTime() + 20_000_000_000L;
            while (!OnEdt.call(() -> window.isShowing() && window.canvas().getWidth() > 0)) {
                if (System.nanoTime() > deadline) {
                    throw new AssertionError("the editor's window did not show");
                }
                Thread.sleep(50);
            }
            Thread.sleep(500);
            List<String> problems = WindowVisibility.problems(window);
            System.out.println("SIZE " + window.getWidth() + "x" + window.getHeight());
            problems.forEach(p -> System.out.println("PROBLEM " + p));
            OnEdt.call(() -> {
                window.dispose();
                return null;
            });
            if (!problems.isEmpty()) {
                throw new AssertionError(problems.size() + " control(s) not seen whole: " + problems);
            }
        });
    }
}

package org.fdnet.hi.app;

import java.nio.file.Path;
import java.util.List;

/**
 * The editor window on a real display opens networks/arms-ja.fdn (EUC-JP, Japanese names): the graph's font
 * displays every name, and the status bar does not say that a name cannot be shown (run by
 * {@link EditorWindowGuiTest}). Prints "SCENARIO PASSED" and exits 0, or what failed and exits 1.
 */
public final class JapaneseNamesScenario {
    private JapaneseNamesScenario() {
    }

    public static void main(String[] args) throws Exception {
        Path file = Path.of(args[0]);
        ScenarioProcess.runAndExit(prefs -> {
            HiWindow window = HiApplication.start(file, new RecentFiles(prefs));
            ShowingComponents.waitFor(window, "the window is shown", () -> window.isShowing() && window.canvas().getWidth() > 0);
            List<String> names = org.fdnet.hi.live.LiveTestNetwork.edt(() -> NamesFont.of(window.current().editor().network()));
            ShowingComponents.check(names.contains("時計") && names.contains("左腕"), "the Japanese names were read: " + names);
            for (String name : names) {
                ShowingComponents.check(org.fdnet.hi.live.LiveTestNetwork.edt(() -> window.namesFont().canDisplayUpTo(name)) == -1,
                        name + " displayable in the graph's font");
            }
            // Read on the Swing thread after opening: a once-only warning would have been posted before this read.
            String status = org.fdnet.hi.live.LiveTestNetwork.edt(() -> window.status().message());
            ShowingComponents.check(!status.contains("cannot be shown"), "no illegible-names warning: " + status);
            javax.swing.SwingUtilities.invokeAndWait(window::dispose);
        });
    }
}

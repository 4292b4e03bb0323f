package org.fdnet.hi.app;

import java.util.prefs.Preferences;

/**
 * The common frame of a GUI scenario run as its own process under Xvfb: throwaway preferences for the editor's
 * recent files, "SCENARIO PASSED" and exit 0 when the body returns, "SCENARIO FAILED: why" (with the stack) and
 * exit 1 when it throws. The JUnit test that starts the process reads that line.
 */
final class ScenarioProcess {
    /** One scenario's work, given its throwaway preferences. */
    interface Body {
        void run(Preferences prefs) throws Exception;
    }

    private ScenarioProcess() {
    }

    static void runAndExit(Body body) {
        Preferences prefs = Preferences.userRoot().node("org/fdnet/hi/test/" + ProcessHandle.current().pid());
        int code = 1;
        try {
            body.run(prefs);
            System.out.println("SCENARIO PASSED");
            code = 0;
        } catch (Throwable t) {
            System.out.println("SCENARIO FAILED: " + t);
            for (StackTraceElement e : t.getStackTrace()) {
                System.out.println("    at " + e);
            }
        } finally {
            try {
                prefs.removeNode();
            } catch (Exception e) {
                System.out.println("could not remove the scenario's preferences: " + e);
            }
        }
        System.exit(code);
    }
}

package org.fdnet.testing;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * Installs Xvfb for the GUI tests when it is missing — as root with apt-get only, like roq-sim's build installs
 * MuJoCo — or fails with the one command a user runs. Never a skip: a GUI test that cannot get a display fails.
 */
final class XvfbInstaller {
    /** The one line a user without root runs (also printed by .ci/run). */
    static final String INSTALL_LINE = "sudo apt-get install -y --no-install-recommends xvfb xauth";

    private XvfbInstaller() {
    }

    /**
     * Xvfb's path after installing it; an {@link AssertionError} naming {@link #INSTALL_LINE} when this process
     * may not install it ({@code root} false or no {@code aptGet}) or the install failed.
     */
    static Path install(boolean root, Path aptGet) throws IOException, InterruptedException {
        String why = "GUI tests need an X display: $DISPLAY is not set and Xvfb is not installed";
        if (!root || aptGet == null) {
            throw new AssertionError(why + "; install it with: " + INSTALL_LINE);
        }
        System.err.println("fdnet tests: installing xvfb xauth (GUI tests open real windows under Xvfb) ...");
        // DPkg::Lock::Timeout: two modules' tests (or a launcher) installing at once wait for each other.
        Process p = new ProcessBuilder(List.of("bash", "-c", "export DEBIAN_FRONTEND=noninteractive; "
                + aptGet + " -o DPkg::Lock::Timeout=300 update -qq && " + aptGet
                + " -o DPkg::Lock::Timeout=300 install -y -qq --no-install-recommends xvfb xauth"))
                .redirectErrorStream(true).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        if (!p.waitFor(10, TimeUnit.MINUTES) || p.exitValue() != 0) {
            throw new AssertionError(why + "; installing it with apt-get failed (" + out.strip() + "); install it with: "
                    + INSTALL_LINE);
        }
        Path xvfb = RealDisplayExtension.onPath("Xvfb");
        if (xvfb == null) {
            throw new AssertionError(why + "; apt-get installed xvfb but Xvfb is not on the PATH");
        }
        return xvfb;
    }
}

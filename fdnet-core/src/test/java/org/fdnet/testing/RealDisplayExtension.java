package org.fdnet.testing;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Assumptions;
import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.extension.ParameterContext;
import org.junit.jupiter.api.extension.ParameterResolutionException;
import org.junit.jupiter.api.extension.ParameterResolver;

/**
 * Gives GUI tests a real X display ({@link RealDisplay} parameter): {@code $DISPLAY} if set; else it
 * starts {@code Xvfb :N -screen 0 1280x1024x24} itself when the binary is on the PATH (and stops it after
 * the test class); else the tests are skipped — except when {@code CI=true}, where a missing display fails
 * them, so CI can never pass a GUI test it did not run.
 *
 * <pre>
 *   &#64;ExtendWith(RealDisplayExtension.class)
 *   class PanelTest { &#64;Test void shouldStart(RealDisplay display) { display.java(Scenario.class).start() ... } }
 * </pre>
 */
public final class RealDisplayExtension implements BeforeAllCallback, ParameterResolver {
    private static final ExtensionContext.Namespace NS = ExtensionContext.Namespace.create(RealDisplayExtension.class);

    @Override
    public void beforeAll(ExtensionContext context) throws Exception {
        String display = System.getenv("DISPLAY");
        if (display != null && !display.isBlank()) {
            context.getStore(NS).put("display", new RealDisplay(display, false));
            return;
        }
        Path xvfb = onPath("Xvfb");
        if (xvfb == null) {
            String why = "no X display: $DISPLAY is not set and Xvfb is not installed "
                    + "(apt-get install -y --no-install-recommends xvfb xauth)";
            if ("true".equals(System.getenv("CI"))) {
                throw new AssertionError(why + " — CI=true, so GUI tests fail instead of being skipped");
            }
            Assumptions.abort(why);
        }
        XvfbServer server = XvfbServer.start(xvfb);
        context.getStore(NS).put("xvfb", server);
        context.getStore(NS).put("display", new RealDisplay(server.display(), true));
    }

    @Override
    public boolean supportsParameter(ParameterContext p, ExtensionContext e) {
        return p.getParameter().getType() == RealDisplay.class;
    }

    @Override
    public Object resolveParameter(ParameterContext p, ExtensionContext e) {
        RealDisplay d = e.getStore(NS).get("display", RealDisplay.class);
        if (d == null) {
            throw new ParameterResolutionException("RealDisplayExtension must be registered on the class");
        }
        return d;
    }

    private static Path onPath(String binary) {
        String path = System.getenv().getOrDefault("PATH", "/usr/bin:/bin");
        for (String dir : path.split(File.pathSeparator)) {
            Path p = Path.of(dir, binary);
            if (Files.isExecutable(p)) {
                return p;
            }
        }
        return null;
    }

    /** An Xvfb process on a free display number; closed (stopped) by JUnit when the class's store closes. */
    static final class XvfbServer implements ExtensionContext.Store.CloseableResource {
        private final Process process;
        private final String display;

        private XvfbServer(Process process, String display) {
            this.process = process;
            this.display = display;
        }

        static XvfbServer start(Path xvfb) throws IOException, InterruptedException {
            for (int n = 90; n < 190; n++) {
                Path socket = Path.of("/tmp/.X11-unix/X" + n);
                if (Files.exists(socket) || Files.exists(Path.of("/tmp/.X" + n + "-lock"))) {
                    continue;
                }
                Process p = new ProcessBuilder(xvfb.toString(), ":" + n, "-screen", "0", "1280x1024x24", "-nolisten", "tcp")
                        .redirectErrorStream(true).redirectOutput(ProcessBuilder.Redirect.DISCARD).start();
                long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
                while (System.nanoTime() < deadline && p.isAlive() && !Files.exists(socket)) {
                    Thread.sleep(50);
                }
                if (p.isAlive() && Files.exists(socket)) {
                    return new XvfbServer(p, ":" + n);
                }
                p.destroyForcibly();
            }
            throw new IOException("could not start Xvfb on any display :90..:189");
        }

        String display() {
            return display;
        }

        @Override
        public void close() throws InterruptedException {
            process.destroy();
            if (!process.waitFor(5, TimeUnit.SECONDS)) {
                process.destroyForcibly();
            }
        }
    }
}

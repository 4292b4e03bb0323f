package org.fdnet.testing;

import java.io.File;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.ExtensionContext;
import org.junit.jupiter.api.extension.ParameterContext;
import org.junit.jupiter.api.extension.ParameterResolutionException;
import org.junit.jupiter.api.extension.ParameterResolver;

/**
 * Gives GUI tests a real X display ({@link RealDisplay} parameter): {@code $DISPLAY} if set; else it
 * starts {@code Xvfb :N -screen 0 1280x1024x24} itself (and stops it after the test class). Xvfb missing:
 * as root with apt-get (CI, a fresh container) it installs {@code xvfb xauth}, as the build installs MuJoCo for
 * roq-sim; otherwise the test class <em>fails</em> with the one line that installs it. A GUI test is never
 * skipped and never reports "Tests run: 0": it runs, or it fails saying why.
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
            xvfb = XvfbInstaller.install(isRoot(), onPath("apt-get"));
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

    private static boolean isRoot() throws IOException {
        return Integer.valueOf(0).equals(Files.getAttribute(Path.of("/proc/self"), "unix:uid"));
    }

    static Path onPath(String binary) {
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

package org.fdnet.roq.view;

import java.awt.Frame;
import java.awt.Point;
import java.awt.Rectangle;
import java.awt.Robot;
import java.awt.image.BufferedImage;
import java.nio.file.Path;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.atomic.AtomicReference;
import javax.imageio.ImageIO;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import org.fdnet.cli.FdnetCommand;
import org.fdnet.testing.WindowVisibility;

/**
 * Run on a real display by {@link DemoWindowDisplayTest}: {@code fdnet demo --gui --for 6s --no-logger
 * --screenshot SHOT} as the CLI runs it, while a watcher finds the demo window on screen, counts its updates twice
 * and that every label is whole at the window's default size ({@link WindowVisibility}), and captures the screen
 * where it stands. Prints {@code STEP …} lines; exit 0 when every step passed.
 * Args: NETWORK SCREENSHOT SCREEN_CAPTURE
 */
public final class DemoWindowScenario {
    private DemoWindowScenario() {
    }

    public static void main(String[] args) throws Exception {
        AtomicReference<String> failure = new AtomicReference<>();
        AtomicInteger exit = new AtomicInteger(-1);
        Thread demo = new Thread(() -> exit.set(FdnetCommand.commandLine().execute("demo", "--gui", "--for", "6s",
                "--no-logger", "--network", args[0], "--screenshot", args[1])), "demo");
        demo.start();
        RoqDemoPanel panel = null;
        long deadline = System.nanoTime() + 60_000_000_000L;
        while (panel == null && System.nanoTime() < deadline) {
            Thread.sleep(100);
            panel = findPanel();
        }
        if (panel == null) {
            fail("the demo window never showed");
        }
        System.out.println("STEP window open");
        Thread.sleep(1500);
        long[] first = onEdt(panel);
        Thread.sleep(1500);
        long[] second = onEdt(panel);
        if (second[0] <= first[0]) {
            fail("the window did not update: " + first[0] + " then " + second[0] + " snapshots shown");
        }
        System.out.println("STEP window updates: " + first[0] + " then " + second[0] + " snapshots, path " + second[1]
                + " points");
        java.util.List<String> problems = WindowVisibility.problems(SwingUtilities.getWindowAncestor(panel));
        if (!problems.isEmpty()) {
            fail("not seen whole at the window's default size: " + problems);
        }
        System.out.println("STEP every label whole at " + SwingUtilities.getWindowAncestor(panel).getSize());
        Rectangle where = onScreen(panel);
        BufferedImage screen = new Robot().createScreenCapture(where);
        ImageIO.write(screen, "png", Path.of(args[2]).toFile());
        System.out.println("STEP screen captured " + where.width + "x" + where.height);
        demo.join(90_000);
        if (demo.isAlive()) {
            fail("fdnet demo did not end");
        }
        System.out.println("STEP demo ended with " + exit.get());
        System.out.println("STEP all passed");
        System.exit(0);
    }

    private static void fail(String why) {
        System.out.println("FAILED " + why);
        System.exit(1);
    }

    private static RoqDemoPanel findPanel() throws Exception {
        AtomicReference<RoqDemoPanel> found = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            for (Frame f : Frame.getFrames()) {
                if (f.isShowing() && f instanceof JFrame j && j.getContentPane() instanceof RoqDemoPanel p) {
                    found.set(p);
                }
            }
        });
        return found.get();
    }

    private static long[] onEdt(RoqDemoPanel panel) throws Exception {
        long[] r = new long[2];
        SwingUtilities.invokeAndWait(() -> {
            r[0] = panel.updates();
            r[1] = panel.pathPoints();
        });
        return r;
    }

    private static Rectangle onScreen(RoqDemoPanel panel) throws Exception {
        AtomicReference<Rectangle> r = new AtomicReference<>();
        SwingUtilities.invokeAndWait(() -> {
            Point p = panel.getLocationOnScreen();
            r.set(new Rectangle(p.x, p.y, panel.getWidth(), panel.getHeight()));
        });
        return r.get();
    }
}

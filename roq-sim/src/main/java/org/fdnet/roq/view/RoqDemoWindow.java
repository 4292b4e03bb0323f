package org.fdnet.roq.view;

import java.lang.reflect.InvocationTargetException;
import javax.swing.JFrame;
import javax.swing.SwingUtilities;
import javax.swing.WindowConstants;
import com.formdev.flatlaf.FlatLightLaf;
import org.fdnet.roq.sim.Heightfield;

/**
 * The {@code fdnet demo --gui} window (FlatLaf): a {@link RoqDemoPanel} in a frame. Closing it stops nothing by
 * itself; the demo asks {@link #isShowing()} on each update and ends early when it was closed.
 */
public final class RoqDemoWindow {
    private final JFrame frame;
    private final RoqDemoPanel panel;

    private RoqDemoWindow(JFrame frame, RoqDemoPanel panel) {
        this.frame = frame;
        this.panel = panel;
    }

    /** Opens the window titled {@code title} on the event dispatch thread and returns once it is shown. */
    public static RoqDemoWindow open(String title, Heightfield terrain) throws InterruptedException {
        RoqDemoWindow[] made = new RoqDemoWindow[1];
        try {
            SwingUtilities.invokeAndWait(() -> {
                FlatLightLaf.setup();
                RoqDemoPanel panel = new RoqDemoPanel(terrain);
                panel.title(title);
                JFrame frame = new JFrame(title);
                frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
                frame.setContentPane(panel);
                frame.pack();
                frame.setLocationByPlatform(true);
                frame.setVisible(true);
                made[0] = new RoqDemoWindow(frame, panel);
            });
        } catch (InvocationTargetException e) {
            throw new IllegalStateException("the demo window does not open: " + e.getCause().getMessage(), e.getCause());
        }
        return made[0];
    }

    /** The window's content. Touch it on the event dispatch thread only. */
    public RoqDemoPanel panel() {
        return panel;
    }

    /** Whether the window is still open. */
    public boolean isShowing() {
        return frame.isDisplayable();
    }

    /** Closes the window (from any thread). */
    public void close() {
        SwingUtilities.invokeLater(frame::dispose);
    }
}

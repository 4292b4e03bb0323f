package org.fdnet.hi.app;

import com.formdev.flatlaf.FlatLightLaf;
import java.nio.file.Path;
import java.util.concurrent.CountDownLatch;
import javax.swing.SwingUtilities;

/** Starts the editor: the FlatLaf look, one {@link HiWindow}, optionally a file opened in it. */
public final class HiApplication {
    private HiApplication() {
    }

    /** Creates and shows the window on the Swing thread; {@code file} may be {@code null}. */
    public static HiWindow start(Path file, RecentFiles recent) throws Exception {
        HiWindow[] window = new HiWindow[1];
        SwingUtilities.invokeAndWait(() -> {
            FlatLightLaf.setup();
            window[0] = new HiWindow(recent);
            if (file != null) {
                window[0].open(file);
            }
            window[0].setLocationByPlatform(true);
            window[0].setVisible(true);
        });
        return window[0];
    }

    /** Blocks until {@code window} is closed. */
    public static void awaitClosed(HiWindow window) throws InterruptedException {
        CountDownLatch closed = new CountDownLatch(1);
        SwingUtilities.invokeLater(() -> {
            window.addWindowListener(new java.awt.event.WindowAdapter() {
                @Override
                public void windowClosed(java.awt.event.WindowEvent e) {
                    closed.countDown();
                }
            });
            if (!window.isDisplayable()) {
                closed.countDown();
            }
        });
        closed.await();
    }
}

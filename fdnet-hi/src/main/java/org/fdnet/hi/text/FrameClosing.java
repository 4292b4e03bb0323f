package org.fdnet.hi.text;

import java.awt.Window;
import java.awt.event.WindowAdapter;
import java.awt.event.WindowEvent;
import javax.swing.JDialog;
import javax.swing.WindowConstants;

/**
 * How every text-based frame ends its construction: it is disposed when closed, its models stop listening to
 * the network then (a frame left listening would keep refreshing an invisible window), and it opens sized to
 * its content beside its owner.
 */
final class FrameClosing {
    private FrameClosing() {
    }

    /** Disposes {@code frame} on close, running {@code detachModels} then; packs it and centres it on {@code owner}. */
    static void finish(JDialog frame, Window owner, Runnable detachModels) {
        frame.setDefaultCloseOperation(WindowConstants.DISPOSE_ON_CLOSE);
        frame.addWindowListener(new WindowAdapter() {
            @Override
            public void windowClosed(WindowEvent e) {
                detachModels.run();
            }
        });
        frame.pack();
        frame.setLocationRelativeTo(owner);
    }
}

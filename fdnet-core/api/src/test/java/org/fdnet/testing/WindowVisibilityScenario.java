package org.fdnet.testing;

import java.awt.BorderLayout;
import java.awt.Dimension;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.JFrame;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTabbedPane;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;

/**
 * A window {@link WindowVisibilityTest} knows the faults of: on its second tab a text field placed past the right
 * edge and a label too long for its width; on its first, a field that fits. Prints each problem found
 * ({@code PROBLEM ...}), then whether the fixed window ({@code fixed} argument) passes.
 */
public final class WindowVisibilityScenario {
    public static void main(String[] args) throws Exception {
        AtomicReference<JFrame> frame = new AtomicReference<>();
        boolean fixed = args.length > 0 && args[0].equals("fixed");
        SwingUtilities.invokeAndWait(() -> {
            JFrame f = new JFrame("visibility check");
            JTabbedPane tabs = new JTabbedPane();
            JPanel first = new JPanel();
            JTextField fits = new JTextField("fits", 8);
            fits.setName("fits");
            first.add(fits);
            tabs.addTab("first", first);
            JPanel second = new JPanel(null);
            JTextField outside = new JTextField("outside", 8);
            outside.setName("outside");
            outside.setBounds(fixed ? 10 : 380, 10, 100, 24);
            JLabel cut = new JLabel("a label far too long to be read whole in sixty pixels");
            cut.setName("cut");
            cut.setBounds(10, 50, fixed ? 380 : 60, 20);
            second.add(outside);
            second.add(cut);
            tabs.addTab("second", second);
            f.add(tabs, BorderLayout.CENTER);
            f.setSize(new Dimension(420, 200));
            f.setVisible(true);
            frame.set(f);
        });
        Thread.sleep(300);
        WindowVisibility.problems(frame.get()).forEach(p -> System.out.println("PROBLEM " + p));
        System.out.println("DONE");
        System.exit(0);
    }
}

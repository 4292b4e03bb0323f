package org.fdnet.hi.app;

import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import javax.swing.ButtonGroup;
import javax.swing.JComboBox;
import javax.swing.JComponent;
import javax.swing.JLabel;
import javax.swing.JOptionPane;
import javax.swing.JPanel;
import javax.swing.JRadioButton;
import javax.swing.JTextField;
import org.fdnet.hi.live.RunChoice;

/**
 * Live → Run: where to run the open network — this machine, distributed through a naming service (offered when
 * its nodes name other hosts), or the simulated RoQ on a course — and, optionally, the logger that records it.
 */
final class RunNetworkDialog {
    static final String[] COURSES = {"flat", "slope", "rubble", "fragile"};

    private RunNetworkDialog() {
    }

    /** Asks; {@code null} when cancelled. {@code previous} fills the fields. */
    static RunChoice ask(HiWindow window, String network, boolean spansHosts, RunChoice previous) {
        JRadioButton here = new JRadioButton("On this machine");
        JRadioButton distributed = new JRadioButton("Distributed over its hosts, naming service:");
        JRadioButton simulated = new JRadioButton("On the simulated RoQ, course:");
        ButtonGroup group = new ButtonGroup();
        group.add(here);
        group.add(distributed);
        group.add(simulated);
        JTextField naming = new JTextField(previous.naming().isEmpty() ? "corbaloc::127.0.0.1:2809/NameService"
                : previous.naming(), 28);
        JComboBox<String> course = new JComboBox<>(COURSES);
        course.setEditable(true); // a course file
        if (!previous.course().isEmpty()) {
            course.setSelectedItem(previous.course());
        }
        JTextField logger = new JTextField(previous.logger(), 16);
        logger.setToolTipText("HOST:PORT of a logger's receiver (fdnet logger: 127.0.0.1:5555); empty: not recorded");
        distributed.setEnabled(spansHosts);
        naming.setEnabled(spansHosts);
        (spansHosts ? distributed : previous.where() == RunChoice.Where.SIMULATED_ROQ ? simulated : here)
                .setSelected(true);
        here.setEnabled(!spansHosts);
        simulated.setEnabled(!spansHosts);
        here.setName("run.here");
        distributed.setName("run.distributed");
        simulated.setName("run.simulated");
        naming.setName("run.naming");
        course.setName("run.course");
        logger.setName("run.logger");

        JPanel panel = new JPanel(new GridBagLayout());
        row(panel, 0, new JLabel("Run " + network + ":"), null);
        row(panel, 1, here, null);
        row(panel, 2, distributed, naming);
        row(panel, 3, simulated, course);
        row(panel, 4, new JLabel("Record with the logger at (optional):"), logger);
        int answer = JOptionPane.showConfirmDialog(window, panel, "Run " + network, JOptionPane.OK_CANCEL_OPTION,
                JOptionPane.QUESTION_MESSAGE);
        if (answer != JOptionPane.OK_OPTION) {
            return null;
        }
        RunChoice choice = distributed.isSelected() ? RunChoice.distributed(naming.getText().trim())
                : simulated.isSelected() ? RunChoice.simulated(String.valueOf(course.getSelectedItem()).trim())
                : RunChoice.thisMachine();
        return choice.withLogger(logger.getText());
    }

    private static void row(JPanel panel, int y, JComponent left, JComponent right) {
        GridBagConstraints c = new GridBagConstraints();
        c.gridy = y;
        c.anchor = GridBagConstraints.WEST;
        c.insets = new Insets(2, 2, 2, 6);
        panel.add(left, c);
        if (right != null) {
            c.gridx = 1;
            c.fill = GridBagConstraints.HORIZONTAL;
            panel.add(right, c);
        }
    }
}

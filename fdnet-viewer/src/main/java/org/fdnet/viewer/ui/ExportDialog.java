package org.fdnet.viewer.ui;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.GridBagConstraints;
import java.awt.GridBagLayout;
import java.awt.Insets;
import java.awt.Window;
import java.nio.file.Path;
import java.time.Instant;
import java.time.LocalTime;
import java.time.ZoneId;
import java.time.format.DateTimeFormatter;
import java.time.format.DateTimeParseException;
import java.util.List;
import java.util.concurrent.ExecutionException;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JComboBox;
import javax.swing.JDialog;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JTextField;
import javax.swing.SwingWorker;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.viewer.source.LoggerConnection;
import org.fdnet.viewer.source.RunInfo;
import org.fdnet.viewer.source.ViewerExport;

/**
 * The Export dialog: the chosen nodes, the time range (clock times of the day on show, prefilled with the visible window),
 * the format (MCAP, long CSV, wide CSV) and the file; Export writes it on a worker thread and says what it wrote
 * (or why not) in the dialog's status line. Component names ({@code exportFile}, {@code exportFormat},
 * {@code exportFrom}, {@code exportTo}, {@code exportRun}, {@code exportStatus}) are for tests.
 */
final class ExportDialog extends JDialog {
    static final String TITLE = "Export";
    private static final DateTimeFormatter CLOCK = DateTimeFormatter.ofPattern("HH:mm:ss.SSS");

    private final LoggerConnection connection;
    private final RunInfo run;
    private final List<LoggedNode> nodes;
    private final long dayStartMicros;
    private final JTextField from = new JTextField(12);
    private final JTextField to = new JTextField(12);
    private final JComboBox<ViewerExport.Format> format = new JComboBox<>(ViewerExport.Format.values());
    private final JTextField file = new JTextField(28);
    private final JLabel status = new JLabel(" ");
    private final JButton export = new JButton("Export");

    ExportDialog(Window owner, LoggerConnection connection, RunInfo run, List<LoggedNode> nodes, long fromMicros,
                 long toMicros) {
        super(owner, TITLE, ModalityType.MODELESS);
        this.connection = connection;
        this.run = run;
        this.nodes = nodes;
        long shown = toMicros > 0 ? toMicros : System.currentTimeMillis() * 1000; // an empty plot shows no day
        this.dayStartMicros = Instant.ofEpochMilli(shown / 1000).atZone(ZoneId.systemDefault()).toLocalDate()
                .atStartOfDay(ZoneId.systemDefault()).toInstant().toEpochMilli() * 1000;
        from.setText(clock(fromMicros));
        to.setText(clock(toMicros));
        file.setText(Path.of(System.getProperty("user.dir"), "fdnet-export.mcap").toString());
        name(from, "exportFrom");
        name(to, "exportTo");
        name(format, "exportFormat");
        name(file, "exportFile");
        name(status, "exportStatus");
        format.addActionListener(e -> file.setText(withExtension(file.getText(), (ViewerExport.Format) format.getSelectedItem())));
        setLayout(new BorderLayout(0, 6));
        add(form(), BorderLayout.CENTER);
        add(buttons(), BorderLayout.SOUTH);
        pack();
        setLocationRelativeTo(owner);
    }

    private static void name(java.awt.Component c, String name) {
        c.setName(name);
    }

    private JPanel form() {
        JPanel p = new JPanel(new GridBagLayout());
        p.setBorder(BorderFactory.createEmptyBorder(8, 8, 0, 8));
        GridBagConstraints g = new GridBagConstraints();
        g.insets = new Insets(2, 4, 2, 4);
        g.anchor = GridBagConstraints.WEST;
        JLabel runLabel = new JLabel(run == null ? "run: not known" : "run: " + run);
        name(runLabel, "exportRun");
        row(p, g, 0, "Nodes", new JLabel(nodes.size() + (nodes.size() == 1 ? " node: " : " nodes: ")
                + String.join(", ", nodes.stream().limit(4).map(LoggerConnection::label).toList())
                + (nodes.size() > 4 ? ", …" : "")));
        row(p, g, 1, "Run", runLabel);
        row(p, g, 2, "From", from);
        row(p, g, 3, "To", to);
        row(p, g, 4, "Format", format);
        JPanel fileRow = new JPanel(new FlowLayout(FlowLayout.LEFT, 0, 0));
        JButton choose = new JButton("Choose…");
        choose.addActionListener(e -> chooseFile());
        fileRow.add(file);
        fileRow.add(choose);
        row(p, g, 5, "File", fileRow);
        g.gridx = 0;
        g.gridy = 6;
        g.gridwidth = 2;
        p.add(status, g);
        return p;
    }

    private static void row(JPanel p, GridBagConstraints g, int y, String label, java.awt.Component c) {
        g.gridx = 0;
        g.gridy = y;
        g.gridwidth = 1;
        p.add(new JLabel(label), g);
        g.gridx = 1;
        p.add(c, g);
    }

    private JPanel buttons() {
        JPanel p = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        JButton close = new JButton("Close");
        close.addActionListener(e -> dispose());
        export.addActionListener(e -> startExport());
        p.add(export);
        p.add(close);
        return p;
    }

    private void chooseFile() {
        JFileChooser chooser = new JFileChooser();
        chooser.setSelectedFile(new java.io.File(file.getText()));
        if (chooser.showSaveDialog(this) == JFileChooser.APPROVE_OPTION) {
            file.setText(chooser.getSelectedFile().getPath());
        }
    }

    /** Checks the fields and writes the file on a worker thread. */
    void startExport() {
        long start;
        long end;
        try {
            start = micros(from.getText(), "From");
            end = micros(to.getText(), "To");
        } catch (IllegalArgumentException e) {
            status.setText(e.getMessage());
            return;
        }
        if (end < start) {
            status.setText("To (" + to.getText() + ") is before From (" + from.getText() + ")");
            return;
        }
        ViewerExport.Format chosen = (ViewerExport.Format) format.getSelectedItem();
        Path target = Path.of(file.getText().trim());
        export.setEnabled(false);
        status.setText("exporting …");
        new SwingWorker<ViewerExport.Written, Void>() {
            @Override
            protected ViewerExport.Written doInBackground() throws Exception {
                return ViewerExport.write(connection, run, nodes, start, end, chosen, target);
            }

            @Override
            protected void done() {
                export.setEnabled(true);
                try {
                    ViewerExport.Written w = get();
                    status.setText(String.format("exported %,d values (%,d bytes) to %s", w.values(), w.bytes(), target));
                } catch (ExecutionException e) {
                    status.setText("export to " + target + " failed: " + e.getCause().getMessage());
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }
        }.execute();
    }

    private String clock(long micros) {
        return CLOCK.format(Instant.ofEpochMilli(micros / 1000).atZone(ZoneId.systemDefault()).toLocalTime());
    }

    private long micros(String text, String field) {
        try {
            LocalTime t = LocalTime.parse(text.trim());
            return dayStartMicros + t.toNanoOfDay() / 1000;
        } catch (DateTimeParseException e) {
            throw new IllegalArgumentException(field + " '" + text + "' is not a clock time like 08:09:30.250");
        }
    }

    private static String withExtension(String path, ViewerExport.Format f) {
        int dot = path.lastIndexOf('.');
        int slash = Math.max(path.lastIndexOf('/'), path.lastIndexOf('\\'));
        String base = dot > slash ? path.substring(0, dot) : path;
        return base + f.extension();
    }
}

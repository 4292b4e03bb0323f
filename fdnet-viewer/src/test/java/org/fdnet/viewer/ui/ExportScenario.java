package org.fdnet.viewer.ui;

import java.awt.Component;
import java.awt.Container;
import java.awt.Window;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.atomic.AtomicReference;
import javax.swing.AbstractButton;
import javax.swing.JComboBox;
import javax.swing.JLabel;
import javax.swing.JTextField;
import javax.swing.SwingUtilities;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.EventClock;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.ValueType;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.logger.InProcessLogger;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.viewer.source.ViewerExport;

/**
 * Run on a real display by {@link ViewerExportDisplayTest}: a logger gets 2,000 values of three Datas (one with a
 * Japanese name); the viewer window's tree chooses two of them, its Export… button opens the dialog, which
 * writes them as MCAP and then as a CSV file, driven through its components as a user would. Prints {@code STEP …}
 * lines and {@code FILE format path values}; exit 0 when every step passed. Args: OUTPUT_FOLDER
 */
public final class ExportScenario {
    static final int VALUES_PER_NODE = 2000;

    private ExportScenario() {
    }

    public static void main(String[] args) throws Exception {
        Path folder = Path.of(args[0]);
        try (InProcessLogger logger = InProcessLogger.throwaway();
             LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(), "export"))) {
            EventClock clock = new EventClock();
            String[] names = {"pitch", "歩幅", "unplotted"};
            for (int n = 0; n < names.length; n++) {
                client.accept(new NodeNamedEvent(n, clock.next(), NodeKind.DATA, new NodeRef("Pose", names[n])));
            }
            for (int k = 0; k < VALUES_PER_NODE; k++) {
                for (int n = 0; n < names.length; n++) {
                    client.accept(new DataValueEvent(n, clock.next(), ValueType.DOUBLE, Double.toString(0.01 * k + n)));
                }
            }
            client.flush(30_000);
            ViewerWindow w = ViewerWindow.open(logger.viewerAddress(), List.of());
            System.out.println("STEP window open");
            SwingUtilities.invokeAndWait(() -> {
                NodeTree tree = find(w, NodeTree.class, c -> true);
                System.out.println("STEP chose " + tree.choose(List.of("Pose/pitch", "Pose/歩幅")) + " Datas");
            });
            for (ViewerExport.Format format : new ViewerExport.Format[] {ViewerExport.Format.MCAP, ViewerExport.Format.CSV}) {
                Path file = folder.resolve("export" + format.extension());
                AtomicReference<ExportDialog> dialog = new AtomicReference<>();
                SwingUtilities.invokeAndWait(() -> {
                    find(w, AbstractButton.class, b -> ExportAction.NAME.equals(((AbstractButton) b).getText())).doClick();
                    for (Window o : w.getOwnedWindows()) {
                        if (o instanceof ExportDialog d && d.isVisible()) {
                            dialog.set(d);
                        }
                    }
                    ExportDialog d = dialog.get();
                    JComboBox<?> formats = find(d, JComboBox.class, c -> "exportFormat".equals(c.getName()));
                    formats.setSelectedItem(format);
                    ((JTextField) find(d, JTextField.class, c -> "exportFile".equals(c.getName()))).setText(file.toString());
                    ((JTextField) find(d, JTextField.class, c -> "exportFrom".equals(c.getName()))).setText("00:00:00");
                    ((JTextField) find(d, JTextField.class, c -> "exportTo".equals(c.getName()))).setText("23:59:59.999");
                    find(d, AbstractButton.class, b -> "Export".equals(((AbstractButton) b).getText())).doClick();
                });
                JLabel status = find(dialog.get(), JLabel.class, c -> "exportStatus".equals(c.getName()));
                long deadline = System.nanoTime() + 60_000_000_000L;
                while (!status.getText().startsWith("exported") && !status.getText().contains("failed")) {
                    if (System.nanoTime() > deadline) {
                        throw new AssertionError("export did not finish: " + status.getText());
                    }
                    Thread.sleep(50);
                }
                System.out.println("STEP " + format.name() + ": " + status.getText());
                if (!status.getText().startsWith("exported") || !Files.exists(file)) {
                    System.out.println("FAILED " + format);
                    System.exit(1);
                }
                System.out.println("FILE " + format.name() + " " + file);
                SwingUtilities.invokeAndWait(() -> dialog.get().dispose());
            }
            SwingUtilities.invokeAndWait(w::dispose);
            System.out.println("STEP all passed");
        }
        System.exit(0);
    }

    @SuppressWarnings("unchecked")
    private static <T> T find(Container root, Class<T> type, java.util.function.Predicate<Component> which) {
        for (Component c : root.getComponents()) {
            if (type.isInstance(c) && which.test(c)) {
                return (T) c;
            }
            if (c instanceof Container inner) {
                T found = findOrNull(inner, type, which);
                if (found != null) {
                    return found;
                }
            }
        }
        throw new AssertionError("no " + type.getSimpleName() + " found in " + root.getClass().getSimpleName());
    }

    private static <T> T findOrNull(Container root, Class<T> type, java.util.function.Predicate<Component> which) {
        try {
            return find(root, type, which);
        } catch (AssertionError notHere) {
            return null;
        }
    }
}

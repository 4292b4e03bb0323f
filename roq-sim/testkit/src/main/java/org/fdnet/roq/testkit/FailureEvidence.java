package org.fdnet.roq.testkit;

import java.io.IOException;
import java.lang.reflect.InvocationTargetException;
import java.nio.channels.FileChannel;
import java.nio.channels.FileLock;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardOpenOption;
import java.sql.SQLException;
import java.util.List;
import java.util.OptionalInt;
import javax.swing.SwingUtilities;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.logger.InProcessLogger;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerConfigFile;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.view.DemoFigures;
import org.fdnet.roq.view.RoqDemoPanel;

/**
 * What a failing robot test leaves behind: a PNG of the robot view (the demo window's drawing: terrain, fragile and
 * broken cells, RoQ, its path, its figures) and the run's events recorded in a logger database, where
 * {@code fdnet logger} and {@code fdnet viewer --replay} open them.
 *
 * <p>Both go under {@code target/fdnet-evidence/} of the directory the tests run in, or the folder named by the
 * system property {@value #FOLDER_PROPERTY}: {@code NAME.png} per failure and {@code logger/} (a PostgreSQL data
 * folder and the {@code logger.properties} that points {@code fdnet logger} at it). Test processes running in
 * parallel take turns on the database through a file lock.
 */
final class FailureEvidence {
    /** System property naming the folder evidence is written to. */
    static final String FOLDER_PROPERTY = "fdnet.testkit.evidence";
    private static final long FLUSH_MILLIS = 60_000;

    private FailureEvidence() {
    }

    /** The evidence folder. */
    static Path folder() {
        String property = System.getProperty(FOLDER_PROPERTY);
        return property != null && !property.isBlank() ? Path.of(property)
                : Path.of("target", "fdnet-evidence").toAbsolutePath();
    }

    /**
     * Writes the picture and the recording of {@code roq}'s run and returns the lines to add to the failure message.
     *
     * @param roq  the failed run (still open)
     * @param name the file-name stem: test class and method
     */
    static String write(SimulatedRoq roq, String name) {
        Path folder = folder();
        StringBuilder lines = new StringBuilder();
        try {
            Files.createDirectories(folder);
            Path png = folder.resolve(name + ".png");
            picture(roq, png);
            lines.append("\n  picture of the robot view: ").append(png);
        } catch (IOException | RuntimeException e) {
            lines.append("\n  no picture of the robot view: ").append(e);
        }
        try {
            lines.append(record(roq, name, folder.resolve("logger")));
        } catch (IOException | SQLException | RuntimeException e) {
            lines.append("\n  the run was not recorded: ").append(e);
        }
        return lines.toString();
    }

    private static void picture(SimulatedRoq roq, Path png) throws IOException {
        RoqMeasures m = roq.measures();
        SensorSnapshot s = roq.snapshot();
        DemoFigures figures = new DemoFigures(m.time(), m.distance(), Double.NaN, m.smallestStabilityMargin(), -1, -1,
                -1, s.brokenCellCount(), roq.network().events().size(), 0, 0, m.fallen());
        IOException[] failed = new IOException[1];
        try {
            SwingUtilities.invokeAndWait(() -> {
                RoqDemoPanel panel = new RoqDemoPanel(roq.simulator().heightfield());
                panel.title(roq.name() + " at t = " + String.format(java.util.Locale.ROOT, "%.2f s", m.time()));
                for (double[] p : roq.trail()) {
                    panel.trace(p[0], p[1]);
                }
                panel.show(s, figures);
                try {
                    panel.writePng(png);
                } catch (IOException e) {
                    failed[0] = e;
                }
            });
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while drawing " + png, e);
        } catch (InvocationTargetException e) {
            throw new IOException("drawing " + png + " failed: " + e.getCause(), e.getCause());
        }
        if (failed[0] != null) {
            throw failed[0];
        }
    }

    private static String record(SimulatedRoq roq, String name, Path folder) throws IOException, SQLException {
        Files.createDirectories(folder);
        Path properties = folder.resolve("logger.properties");
        try (FileChannel lockFile = FileChannel.open(folder.resolve(".lock"), StandardOpenOption.CREATE,
                StandardOpenOption.WRITE); FileLock ignored = lockFile.lock()) {
            LoggerConfig saved = new LoggerConfig().set(LoggerSetting.DATABASE_DIRECTORY, folder.resolve("db").toString())
                    .set(LoggerSetting.DATABASE_FSYNC, "false");
            LoggerConfigFile.save(saved, properties);
            LoggerConfig config = LoggerConfigFile.load(properties).set(LoggerSetting.RECEIVER_PORT, "0")
                    .set(LoggerSetting.SENDER_PORT, "0");
            try (InProcessLogger logger = InProcessLogger.of(config)) {
                LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(),
                        "fdnet test " + name));
                List<NetworkEvent> events = roq.network().events();
                for (NetworkEvent e : events) {
                    client.accept(e);
                }
                boolean committed = client.flush(FLUSH_MILLIS);
                OptionalInt run = logger.logger().directory().runIdOf(client.run());
                client.close();
                if (!committed || run.isEmpty()) {
                    return "\n  the run was not recorded: the logger did not commit its " + events.size()
                            + " events within " + FLUSH_MILLIS / 1000 + " s";
                }
                return String.format(java.util.Locale.ROOT, "%n  recording: run %d (%,d events) in %s%n  replay it:"
                        + " bin/fdnet logger --config %s   then   bin/fdnet viewer --replay %d", run.getAsInt(),
                        events.size(), folder, properties, run.getAsInt());
            }
        }
    }
}

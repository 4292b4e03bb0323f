package org.fdnet.logger.ui;

import java.awt.BorderLayout;
import java.awt.FlowLayout;
import java.awt.GridLayout;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import javax.swing.BorderFactory;
import javax.swing.JButton;
import javax.swing.JFileChooser;
import javax.swing.JLabel;
import javax.swing.JPanel;
import javax.swing.JScrollPane;
import javax.swing.JTabbedPane;
import javax.swing.JTable;
import javax.swing.SwingWorker;
import javax.swing.Timer;
import org.fdnet.logger.LoggerStatus;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerConfigFile;
import org.fdnet.logger.config.LoggerSetting;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The logger's configuration panel (thesis, chapter 4 VIII): one tab per panel of parameters — database,
 * writer, receiver (with its clients), sender (with its clients), memory and priority — plus the cache
 * browser ({@link CacheBrowser}); Start, Stop and <em>Retry database</em> (enabled once the writer reported
 * the database DOWN), and the live status: cache used/free, events per second in and out, database state and lag.
 * Each field is checked as it is typed ({@link SettingField}). Start validates every field (the first bad one is
 * shown with its precise message), saves the panel's file, seals the configuration and starts the logger off the
 * event thread; while it runs only the live settings stay editable, and a new valid value of one is applied to the
 * running logger at Enter or when the field is left, and saved. Load… and Save… read and write a configuration file.
 *
 * <p>Component names (for tests): {@code start}, {@code stop}, {@code retry}, {@code load}, {@code save},
 * {@code status}, {@code message}, and each field is named by its setting's key.
 */
public final class LoggerPanel extends JPanel {
    private static final Logger LOG = LoggerFactory.getLogger(LoggerPanel.class);

    private Path file;
    private final List<SettingsTab> tabs = new ArrayList<>();
    private final ClientTableModel cores = new ClientTableModel();
    private final ClientTableModel viewers = new ClientTableModel();
    private final JButton start = new JButton("Start");
    private final JButton stop = new JButton("Stop");
    private final JButton retry = new JButton("Retry database");
    private final JButton load = new JButton("Load…");
    private final JButton save = new JButton("Save…");
    private final JLabel cacheLabel = new JLabel("cache: -");
    private final JLabel rateLabel = new JLabel("events/s: -");
    private final JLabel databaseLabel = new JLabel("database: -");
    private final JLabel status = new JLabel("stopped");
    private final JLabel message = new JLabel(" ");
    private final Timer refresh;
    private LoggerConfig config;
    private volatile NetworkStateLogger logger;

    public LoggerPanel(LoggerConfig config, Path file) {
        super(new BorderLayout(6, 6));
        this.config = config;
        this.file = file;
        JTabbedPane pane = new JTabbedPane();
        pane.setName("tabs");
        for (LoggerSetting.Panel p : LoggerSetting.Panel.values()) {
            SettingsTab tab = new SettingsTab(p, config, this::applyLive);
            tabs.add(tab);
            if (p == LoggerSetting.Panel.RECEIVER || p == LoggerSetting.Panel.SENDER) {
                JPanel withClients = new JPanel(new BorderLayout());
                withClients.add(tab, BorderLayout.NORTH);
                JTable table = new JTable(p == LoggerSetting.Panel.RECEIVER ? cores : viewers);
                table.setName(p == LoggerSetting.Panel.RECEIVER ? "cores" : "viewers");
                JScrollPane scroll = new JScrollPane(table);
                scroll.setBorder(BorderFactory.createTitledBorder("Connected clients"));
                withClients.add(scroll, BorderLayout.CENTER);
                pane.addTab(p.title(), withClients);
            } else {
                JScrollPane scroll = new JScrollPane(tab);
                scroll.setBorder(BorderFactory.createEmptyBorder());
                pane.addTab(p.title(), scroll);
            }
        }
        CacheBrowser browser = new CacheBrowser(() -> logger);
        pane.addTab("Cache", browser);
        pane.addChangeListener(e -> {
            if (pane.getSelectedComponent() == browser) {
                browser.refresh();
            }
        });
        add(pane, BorderLayout.CENTER);
        add(southPanel(), BorderLayout.SOUTH);
        start.setName("start");
        stop.setName("stop");
        retry.setName("retry");
        retry.setToolTipText("after the writer reported the database DOWN (its reconnection attempts used up): try again");
        retry.setEnabled(false);
        retry.addActionListener(e -> retryDatabase());
        load.setName("load");
        save.setName("save");
        load.setToolTipText("read the settings from a configuration file");
        save.setToolTipText("write the settings to a configuration file (Start also saves them)");
        load.addActionListener(e -> chooseFile(true));
        save.addActionListener(e -> chooseFile(false));
        status.setName("status");
        cacheLabel.setName("cache");
        rateLabel.setName("rates");
        databaseLabel.setName("database");
        message.setName("message");
        stop.setEnabled(false);
        start.addActionListener(e -> startLogger());
        stop.addActionListener(e -> stopLogger());
        refresh = new Timer(500, e -> showStatus());
        refresh.start();
    }

    private JPanel southPanel() {
        JPanel statusPanel = new JPanel(new GridLayout(0, 1));
        statusPanel.setBorder(BorderFactory.createTitledBorder("Logger's real-time information"));
        statusPanel.add(status);
        statusPanel.add(cacheLabel);
        statusPanel.add(rateLabel);
        statusPanel.add(databaseLabel);
        JPanel buttons = new JPanel(new BorderLayout());
        message.setBorder(BorderFactory.createEmptyBorder(0, 6, 0, 6));
        buttons.add(message, BorderLayout.CENTER);
        JPanel files = new JPanel(new FlowLayout(FlowLayout.LEFT));
        files.add(load);
        files.add(save);
        buttons.add(files, BorderLayout.WEST);
        JPanel actions = new JPanel(new FlowLayout(FlowLayout.RIGHT));
        buttons.add(actions, BorderLayout.EAST);
        actions.add(start);
        actions.add(stop);
        actions.add(retry);
        JPanel south = new JPanel(new BorderLayout());
        south.add(statusPanel, BorderLayout.CENTER);
        south.add(buttons, BorderLayout.SOUTH);
        return south;
    }

    public NetworkStateLogger logger() {
        return logger;
    }

    /** The fields as a config, or null when one is invalid (its message shown). */
    private LoggerConfig fieldsConfig() {
        LoggerConfig next = new LoggerConfig();
        try {
            for (SettingsTab t : tabs) {
                t.applyTo(next);
            }
            next.validate();
            return next;
        } catch (IllegalArgumentException e) {
            message.setText(e.getMessage());
            return null;
        }
    }

    /** Writes the fields to {@code target}, which becomes the panel's file; false (and why, shown) when not. */
    public boolean save(Path target) {
        LoggerConfig next = fieldsConfig();
        if (next == null) {
            return false;
        }
        try {
            LoggerConfigFile.save(next, target);
        } catch (IOException e) {
            message.setText("cannot save " + target + ": " + e.getMessage());
            return false;
        }
        file = target;
        message.setText("saved to " + target);
        return true;
    }

    /** Reads {@code source} into the fields (nothing changes when it is refused: the reason is shown). */
    public boolean load(Path source) {
        try {
            LoggerConfig read = LoggerConfigFile.load(source);
            tabs.forEach(t -> t.show(read));
            file = source;
            message.setText("loaded " + source);
            return true;
        } catch (IOException | IllegalArgumentException e) {
            message.setText("cannot load " + source + ": " + e.getMessage());
            return false;
        }
    }

    private void chooseFile(boolean open) {
        JFileChooser chooser = new JFileChooser(file.toAbsolutePath().getParent() == null ? null
                : file.toAbsolutePath().getParent().toFile());
        chooser.setSelectedFile(file.toFile());
        int answer = open ? chooser.showOpenDialog(this) : chooser.showSaveDialog(this);
        if (answer == JFileChooser.APPROVE_OPTION) {
            if (open) {
                load(chooser.getSelectedFile().toPath());
            } else {
                save(chooser.getSelectedFile().toPath());
            }
        }
    }

    private void applyLive(LoggerSetting setting, String value) {
        NetworkStateLogger running = logger;
        if (running == null) {
            return;
        }
        try {
            running.applyLive(setting, value);
            LoggerConfigFile.save(running.config(), file);
            message.setText(setting.label() + " = " + value + " applied to the running logger");
        } catch (IOException e) {
            message.setText(setting.label() + " applied, but " + file + " could not be saved: " + e.getMessage());
        } catch (IllegalArgumentException | IllegalStateException e) {
            message.setText(e.getMessage());
        }
    }

    private void startLogger() {
        LoggerConfig next = fieldsConfig();
        if (next == null) {
            return;
        }
        try {
            LoggerConfigFile.save(next, file);
        } catch (IOException e) {
            message.setText("cannot save " + file + ": " + e.getMessage());
            return;
        }
        config = next;
        start.setEnabled(false);
        load.setEnabled(false);
        tabs.forEach(t -> t.setRunning(true));
        message.setText("starting…");
        NetworkStateLogger starting = new NetworkStateLogger(next);
        new SwingWorker<Void, Void>() {
            @Override
            protected Void doInBackground() throws Exception {
                starting.start();
                return null;
            }

            @Override
            protected void done() {
                try {
                    get();
                    logger = starting;
                    stop.setEnabled(true);
                    message.setText("started");
                } catch (Exception e) {
                    Throwable cause = e.getCause() != null ? e.getCause() : e;
                    LOG.error("logger did not start", cause);
                    message.setText("cannot start: " + cause.getMessage());
                    start.setEnabled(true);
                    load.setEnabled(true);
                    tabs.forEach(t -> t.setRunning(false));
                }
            }
        }.execute();
    }

    private void stopLogger() {
        NetworkStateLogger running = logger;
        if (running == null) {
            return;
        }
        stop.setEnabled(false);
        message.setText("stopping (writing what the cache holds)…");
        new SwingWorker<Void, Void>() {
            @Override
            protected Void doInBackground() {
                running.stop();
                return null;
            }

            @Override
            protected void done() {
                logger = null;
                start.setEnabled(true);
                load.setEnabled(true);
                tabs.forEach(t -> t.setRunning(false));
                message.setText("stopped");
            }
        }.execute();
    }

    private void retryDatabase() {
        NetworkStateLogger running = logger;
        if (running != null) {
            running.retryDatabase();
            retry.setEnabled(false);
            message.setText("retrying the database…");
        }
    }

    private void showStatus() {
        NetworkStateLogger l = logger;
        LoggerStatus s = l == null ? null : l.status();
        if (s == null || !s.running()) {
            status.setText("stopped");
            retry.setEnabled(false);
            return;
        }
        retry.setEnabled(s.database().startsWith("DOWN"));
        status.setText(String.format("running — cores on %s:%d, viewers on %s:%d", config.receiverAddress(),
                l.receiverPort(), config.senderAddress(), l.senderPort()));
        cacheLabel.setText(String.format("cache: used %,d KiB, free %,d KiB (%.1f %%)%s, %,d events held, %,d monitored",
                s.cache().usedBytes() >> 10, s.cache().freeBytes() >> 10, s.cache().usedPercent(),
                s.cache().pressured() ? " — critical level: receivers paused" : "", s.cache().events(),
                s.cache().monitored()));
        rateLabel.setText(String.format("events/s: in %,.0f, out %,.0f (received %,d, committed %,d)",
                s.eventsInPerSecond(), s.eventsOutPerSecond(), s.cache().received(), s.cache().committed()));
        databaseLabel.setText(String.format("database: %s, lag %d ms (%,d unwritten), batch %,d (max %,d), %d writer connection%s",
                s.database(), s.cache().lagMillis(), s.cache().unwritten(), s.batchRows(), s.maxBatchRows(),
                s.writerConnections(), s.writerConnections() == 1 ? "" : "s"));
        cores.update(s.cores());
        viewers.update(s.viewers());
    }

    /** Stops the refresh timer and the logger (window closing). */
    public void dispose() {
        refresh.stop();
        NetworkStateLogger l = logger;
        if (l != null) {
            l.stop();
        }
    }
}

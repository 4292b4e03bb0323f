package org.fdnet.logger.cli;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import org.fdnet.logger.LoggerStatus;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerConfigFile;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.logger.ui.LoggerFrame;
import org.fdnet.tls.TlsOptions;
import picocli.CommandLine.Command;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code fdnet logger}: starts the network state logger (embedded PostgreSQL unless {@code --db}) and
 * prints a status line every few seconds, and reads commands on standard input ({@link LoggerPrompt}:
 * {@code retry}, {@code status}, {@code help}); {@code --gui} opens the configuration panel instead.
 */
@Command(name = "logger", mixinStandardHelpOptions = true,
        description = {"Start the network state logger: cores connect to the receiver port, viewers to the sender port.",
                "Headless, it reads commands on standard input: retry (try a database reported DOWN again), status, help."})
public final class LoggerCommand implements Callable<Integer> {
    @Mixin
    DatabaseOptions database;

    @Option(names = "--receiver-port", paramLabel = "P", description = "port for cores (default 5555)")
    Integer receiverPort;

    @Option(names = "--sender-port", paramLabel = "P", description = "port for viewers (default 5556)")
    Integer senderPort;

    @Option(names = "--bind", paramLabel = "ADDR",
            description = "address both ports listen on (default 127.0.0.1, or the configuration file's); another"
                    + " address needs --tls or --insecure")
    String bind;

    @Mixin
    TlsOptions tls;

    @Spec
    CommandSpec spec;

    @Option(names = "--config", paramLabel = "FILE", description = "configuration file (default ~/.fdnet/logger.properties)")
    Path configFile;

    @Option(names = "--gui", description = "open the configuration panel (Start/Stop, live status)")
    boolean gui;

    @Option(names = "--status-every", paramLabel = "SECONDS", defaultValue = "5",
            description = "headless status line interval (default 5)")
    int statusSeconds;

    @Option(names = "--screenshot", paramLabel = "PNG", hidden = true,
            description = "render the configuration panel to a PNG and exit (for the docs)")
    Path screenshot;

    @Override
    public Integer call() throws Exception {
        Path file = configFile != null ? configFile : LoggerConfigFile.defaultPath();
        LoggerConfig config;
        try {
            config = LoggerConfigFile.load(file);
            database.applyTo(config);
            if (receiverPort != null) {
                config.set(LoggerSetting.RECEIVER_PORT, receiverPort.toString());
            }
            if (senderPort != null) {
                config.set(LoggerSetting.SENDER_PORT, senderPort.toString());
            }
            if (bind != null) {
                config.set(LoggerSetting.RECEIVER_ADDRESS, bind).set(LoggerSetting.SENDER_ADDRESS, bind);
            }
            config.validate();
            if (screenshot == null) {
                tls.apply();
                tls.requireSafeBind("the logger's receiver port (cores)", config.receiverAddress());
                tls.requireSafeBind("the logger's viewer port", config.senderAddress());
            }
        } catch (IllegalArgumentException | IllegalStateException e) {
            spec.commandLine().getErr().println("fdnet logger: " + e.getMessage());
            spec.commandLine().getErr().flush();
            return 2;
        }
        if (screenshot != null) {
            LoggerFrame.screenshot(config, file, screenshot);
            System.out.println("wrote " + screenshot);
            return 0;
        }
        if (gui) {
            LoggerFrame.open(config, file);
            new CountDownLatch(1).await();
            return 0;
        }
        return headless(config);
    }

    private int headless(LoggerConfig config) throws Exception {
        NetworkStateLogger logger = new NetworkStateLogger(config);
        try {
            logger.start();
        } catch (Exception e) {
            System.err.println("fdnet logger: cannot start: " + e.getMessage());
            return 1;
        }
        // Ctrl-C / TERM stop the logger *before* the JVM's shutdown hooks run: the embedded PostgreSQL library
        // stops its server from a hook of its own, which would race the writer's final drain.
        for (String name : new String[] {"INT", "TERM"}) {
            sun.misc.Signal.handle(new sun.misc.Signal(name), signal -> new Thread(() -> {
                System.out.println("fdnet logger: stopping (writing what the cache holds) ...");
                logger.stop();
                System.exit(0);
            }, "fdnet-logger-stop").start());
        }
        // HUP: after the writer reported the database DOWN (its reconnect attempts used up), try again.
        sun.misc.Signal.handle(new sun.misc.Signal("HUP"), signal -> {
            System.out.println("fdnet logger: told to retry the database");
            logger.retryDatabase();
        });
        System.out.printf("fdnet logger: cores -> %s:%d, viewers -> %s:%d%s (Ctrl-C stops; type retry, or kill -HUP "
                + ProcessHandle.current().pid() + ", to retry a database reported DOWN; help lists the commands)%n",
                config.receiverAddress(), logger.receiverPort(), config.senderAddress(), logger.senderPort(),
                tls.tls() ? ", mutual TLS" : "");
        System.out.flush();
        // A logger started in the background of an interactive shell must not be stopped (SIGTTIN) for reading
        // its terminal: with TTIN ignored the read fails instead, and only the prompt ends.
        sun.misc.Signal.handle(new sun.misc.Signal("TTIN"), sun.misc.SignalHandler.SIG_IGN);
        Thread prompt = new Thread(new LoggerPrompt(logger, new BufferedReader(new InputStreamReader(System.in,
                StandardCharsets.UTF_8)), System.out), "fdnet-logger-prompt");
        prompt.setDaemon(true);
        prompt.start();
        while (logger.running()) {
            Thread.sleep(statusSeconds * 1000L);
            LoggerStatus s = logger.status();
            if (s.running()) {
                System.out.println(s.line());
                System.out.flush();
            }
        }
        return 0;
    }
}

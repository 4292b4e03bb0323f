package org.fdnet.logger.soak;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.corba.OrbSettings;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.logger.store.EmbeddedDatabase;

/**
 * The processes of a soak, each one a real FDNet process that the soak can kill and start again with the same
 * arguments: PostgreSQL (embedded, in this JVM, on a fixed port so the logger finds it again), the logger, the naming
 * service, the hosts and the run. Where they run — all on 127.0.0.1, or each on a host of an apart rig — is the
 * {@link SoakPlacement}'s. Apart, the logger reaches PostgreSQL through a relay on its own host (socat, from its
 * loopback to PostgreSQL's Unix socket: the file system is shared, the loopback is not), so a black-holed logger still
 * reaches its database. {@link #close()} ends every one of them.
 */
final class SoakCluster implements AutoCloseable {
    /** How long the logger host's relay to PostgreSQL may take to listen. */
    private static final long RELAY_TIMEOUT_MILLIS = 10_000;
    private static final long START_TIMEOUT_MILLIS = 120_000;
    private static final String LOGGER_READY = "fdnet logger: cores ->";
    /** How often each host prints what it holds for unreachable peers ({@code fdnet host --health-every}). */
    static final int HEALTH_EVERY_SECONDS = 1;

    private final Path work;
    private final SoakPlacement placement;
    private final int databasePort = FdnetChildProcess.freePort();
    private final int receiverPort = FdnetChildProcess.freePort();
    private final int namingPort = FdnetChildProcess.freePort();
    private final Map<String, List<String>> arguments = new LinkedHashMap<>();
    private final Map<String, String> readyLines = new LinkedHashMap<>();
    private final Map<String, FdnetChildProcess> processes = new LinkedHashMap<>();
    private EmbeddedDatabase database;
    private DatabaseTarget target;
    private Path socketDirectory;
    private Process relay;

    SoakCluster(Path work, SoakPlacement placement) {
        this.work = work;
        this.placement = placement;
    }

    /** Starts PostgreSQL, the logger, the naming service and the hosts; the run comes last ({@link #startRun}). */
    void start(List<String> hosts, String linkFaults) throws IOException {
        if (placement.rig() != null) {
            socketDirectory = Files.createTempDirectory(Path.of("/tmp"), "fdnet-soak-pg");
        }
        startDatabase();
        startRelay();
        int senderPort = FdnetChildProcess.freePort();
        // apart, the same URL reaches the relay on the logger host's loopback
        List<String> logger = new ArrayList<>(List.of("logger", "--db", databaseTarget().url(), "--db-user",
                databaseTarget().user(), "--receiver-port", Integer.toString(receiverPort), "--sender-port",
                Integer.toString(senderPort), "--config", work.resolve("logger.properties").toString(),
                "--status-every", "3600"));
        logger.addAll(placement.bindOptions("logger"));
        define("logger", logger, LOGGER_READY);
        List<String> naming = new ArrayList<>(List.of("naming", "--port", Integer.toString(namingPort)));
        naming.addAll(placement.bindOptions("naming"));
        define("naming", naming, "fdnet naming ready");
        startProcess("logger");
        startProcess("naming");
        for (String host : hosts) {
            List<String> args = new ArrayList<>(List.of("host", "--name", host, "--naming", namingCorbaloc(),
                    "--link-faults", linkFaults, "--health-every", Integer.toString(HEALTH_EVERY_SECONDS)));
            args.addAll(placement.bindOptions(host));
            define(host, args, "fdnet host " + host + " ready");
            startProcess(host);
        }
    }

    /** {@code fdnet run FILE} as host {@code operator}, recording with the logger; commands go to its input. */
    FdnetChildProcess startRun(Path network, long forSeconds, int hosts) {
        List<String> args = new ArrayList<>(List.of("run", network.toString(), "--naming", namingCorbaloc(), "--as",
                "operator", "--for", forSeconds + "s", "--logger", loggerAddress(), "--no-control"));
        args.addAll(placement.bindOptions("operator"));
        define("run", args, "running on " + hosts + " hosts");
        return startProcess("run");
    }

    private String namingCorbaloc() {
        return OrbSettings.namingCorbaloc(placement.address("naming"), namingPort);
    }

    String loggerAddress() {
        return placement.address("logger") + ":" + receiverPort;
    }

    DatabaseTarget databaseTarget() {
        return target;
    }

    /** {@code kill -9}. */
    void kill(String name) {
        processes.get(name).kill();
    }

    /** Starts {@code name} again with the arguments it first had; returns once it says it is ready. */
    FdnetChildProcess startProcess(String name) {
        String host = name.equals("run") ? "operator" : name;
        FdnetChildProcess p = FdnetChildProcess.start(name, placement.launchPrefix(host), List.of(), arguments.get(name),
                readyLines.get(name), START_TIMEOUT_MILLIS);
        processes.put(name, p);
        return p;
    }

    void startDatabase() throws IOException {
        database = socketDirectory == null ? EmbeddedDatabase.start(work.resolve("pg"), databasePort)
                : EmbeddedDatabase.start(work.resolve("pg"), databasePort, socketDirectory);
        target = database.target();
    }

    /** A fast shutdown of PostgreSQL: what it committed stays, every connection is cut. */
    void stopDatabase() throws IOException {
        database.close();
        database = null;
    }

    /** Apart: PostgreSQL's port on the logger host's loopback, relayed to its Unix socket here. */
    private void startRelay() throws IOException {
        if (socketDirectory == null) {
            return;
        }
        Path socket = socketDirectory.resolve(".s.PGSQL." + databasePort);
        List<String> argv = placement.launchPrefix("logger");
        List<String> command = new ArrayList<>(argv);
        command.addAll(List.of("socat", "TCP-LISTEN:" + databasePort + ",bind=127.0.0.1,reuseaddr,fork",
                "UNIX-CONNECT:" + socket));
        try {
            relay = new ProcessBuilder(command).redirectErrorStream(true)
                    .redirectOutput(work.resolve("relay.log").toFile()).start();
        } catch (IOException e) {
            throw new IOException("cannot start the logger host's relay to PostgreSQL (" + String.join(" ", command)
                    + "): " + e.getMessage() + "; it needs socat: apt-get install -y socat", e);
        }
        awaitRelay(argv);
    }

    /**
     * Returns once the relay listens on the logger host's loopback (the logger gives up at once on a refused
     * database connection), asking {@code ss} on that host.
     */
    private void awaitRelay(List<String> onLoggerHost) throws IOException {
        List<String> listening = new ArrayList<>(onLoggerHost);
        listening.addAll(List.of("ss", "-Hltn", "sport = :" + databasePort));
        long deadline = System.nanoTime() + RELAY_TIMEOUT_MILLIS * 1_000_000L;
        while (true) {
            if (!relay.isAlive()) {
                throw new IOException("the logger host's relay to PostgreSQL stopped: "
                        + Files.readString(work.resolve("relay.log")).strip());
            }
            Process ss = new ProcessBuilder(listening).redirectErrorStream(true).start();
            String out = new String(ss.getInputStream().readAllBytes(), java.nio.charset.StandardCharsets.UTF_8);
            try {
                ss.waitFor();
                if (!out.isBlank() && ss.exitValue() == 0) {
                    return;
                }
                if (System.nanoTime() > deadline) {
                    throw new IOException("the logger host's relay to PostgreSQL did not listen on 127.0.0.1:"
                            + databasePort + " within " + RELAY_TIMEOUT_MILLIS + " ms");
                }
                Thread.sleep(50);
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new IOException("interrupted while waiting for the relay to PostgreSQL", e);
            }
        }
    }

    private void define(String name, List<String> args, String ready) {
        arguments.put(name, args);
        readyLines.put(name, ready);
    }

    @Override
    public void close() {
        List<String> names = new ArrayList<>(processes.keySet());
        for (int i = names.size() - 1; i >= 0; i--) {
            processes.get(names.get(i)).stop(10_000);
        }
        if (relay != null) {
            relay.destroyForcibly();
        }
        try {
            if (database != null) {
                database.close();
            }
        } catch (IOException e) {
            throw new java.io.UncheckedIOException("cannot stop the soak's PostgreSQL", e);
        } finally {
            deleteSocketDirectory();
        }
    }

    private void deleteSocketDirectory() {
        if (socketDirectory != null) {
            try (var left = Files.list(socketDirectory)) {
                for (Path p : (Iterable<Path>) left::iterator) {
                    Files.deleteIfExists(p);
                }
                Files.deleteIfExists(socketDirectory);
            } catch (IOException e) {
                // a socket PostgreSQL left behind; /tmp is cleaned by the system
            }
        }
    }

    FdnetChildProcess process(String name) {
        return processes.get(name);
    }

    /** The names of the processes started so far (the run's is {@code run}). */
    List<String> names() {
        return List.copyOf(processes.keySet());
    }
}

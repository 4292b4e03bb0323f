package org.fdnet.logger.soak;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.logger.store.EmbeddedDatabase;

/**
 * The processes of a soak, each one a real FDNet process on 127.0.0.1 that the soak can kill and start again with the
 * same arguments: PostgreSQL (embedded, in this JVM, on a fixed port so the logger finds it again), the logger, the
 * naming service, the hosts and the run. {@link #close()} ends every one of them.
 */
final class SoakCluster implements AutoCloseable {
    private static final long START_TIMEOUT_MILLIS = 120_000;
    private static final String LOGGER_READY = "fdnet logger: cores ->";

    private final Path work;
    private final int databasePort = FdnetChildProcess.freePort();
    private final int receiverPort = FdnetChildProcess.freePort();
    private final int namingPort = FdnetChildProcess.freePort();
    private final Map<String, List<String>> arguments = new LinkedHashMap<>();
    private final Map<String, String> readyLines = new LinkedHashMap<>();
    private final Map<String, FdnetChildProcess> processes = new LinkedHashMap<>();
    private EmbeddedDatabase database;
    private DatabaseTarget target;

    SoakCluster(Path work) {
        this.work = work;
    }

    /** Starts PostgreSQL, the logger, the naming service and the hosts; the run comes last ({@link #startRun}). */
    void start(List<String> hosts, String linkFaults) throws IOException {
        startDatabase();
        int senderPort = FdnetChildProcess.freePort();
        define("logger", List.of("logger", "--db", databaseTarget().url(), "--db-user", databaseTarget().user(),
                "--receiver-port", Integer.toString(receiverPort), "--sender-port", Integer.toString(senderPort),
                "--config", work.resolve("logger.properties").toString(), "--status-every", "3600"), LOGGER_READY);
        define("naming", List.of("naming", "--port", Integer.toString(namingPort)), "fdnet naming ready");
        startProcess("logger");
        startProcess("naming");
        for (String host : hosts) {
            define(host, List.of("host", "--name", host, "--naming-port", Integer.toString(namingPort),
                    "--link-faults", linkFaults), "fdnet host " + host + " ready");
            startProcess(host);
        }
    }

    /** {@code fdnet run FILE} as host {@code operator}, recording with the logger; commands go to its input. */
    FdnetChildProcess startRun(Path network, long forSeconds, int hosts) {
        define("run", List.of("run", network.toString(), "--naming-port", Integer.toString(namingPort), "--as", "operator",
                "--for", forSeconds + "s", "--logger", loggerAddress(), "--no-control"), "running on " + hosts + " hosts");
        return startProcess("run");
    }

    String loggerAddress() {
        return "127.0.0.1:" + receiverPort;
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
        FdnetChildProcess p = FdnetChildProcess.start(name, arguments.get(name), readyLines.get(name), START_TIMEOUT_MILLIS);
        processes.put(name, p);
        return p;
    }

    void startDatabase() throws IOException {
        database = EmbeddedDatabase.start(work.resolve("pg"), databasePort);
        target = database.target();
    }

    /** A fast shutdown of PostgreSQL: what it committed stays, every connection is cut. */
    void stopDatabase() throws IOException {
        database.close();
        database = null;
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
        if (database != null) {
            try {
                database.close();
            } catch (IOException e) {
                throw new java.io.UncheckedIOException("cannot stop the soak's PostgreSQL", e);
            }
        }
    }

    FdnetChildProcess process(String name) {
        return processes.get(name);
    }
}

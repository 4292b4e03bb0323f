package org.fdnet.corba;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * JacORB's Naming Service ({@code org.jacorb.naming.NameServer}) run in this JVM: the directory in which
 * hosts register. It answers {@code corbaloc::ADDRESS:PORT/NameService}.
 */
public final class NamingService {
    private static final String STATE_PREFIX = "fdnet-naming-";
    private static final Logger LOG = LoggerFactory.getLogger(NamingService.class);

    private NamingService() {
    }

    /**
     * Starts the NameServer on a daemon thread and returns once its port accepts connections.
     *
     * @throws IllegalStateException when it does not listen within {@code timeoutMillis}
     */
    public static String start(OrbSettings settings, long timeoutMillis) {
        if (settings.port() == 0) {
            throw new IllegalArgumentException("the naming service needs a fixed port (clients must know it)");
        }
        requireFree(settings);
        OrbRuntime.prepareJvm();
        Path state = stateDirectory();
        List<String> args = new ArrayList<>();
        for (Map.Entry<Object, Object> e : settings.toNamingServerProperties(state).entrySet()) {
            args.add("-D" + e.getKey() + "=" + e.getValue());
        }
        Thread server = new Thread(() -> org.jacorb.naming.NameServer.main(args.toArray(String[]::new)),
                "fdnet-naming");
        server.setDaemon(true);
        server.start();
        long deadline = System.nanoTime() + timeoutMillis * 1_000_000L;
        while (System.nanoTime() < deadline) {
            try (Socket s = new Socket()) {
                s.connect(new InetSocketAddress(settings.bindAddress(), settings.port()), 200);
                String corbaloc = OrbSettings.namingCorbaloc(settings.bindAddress(), settings.port());
                LOG.info("naming service listening: {}", corbaloc);
                return corbaloc;
            } catch (IOException notYet) {
                if (!server.isAlive()) {
                    break;
                }
                sleep(50);
            }
        }
        throw new IllegalStateException("the naming service did not listen on " + settings.bindAddress() + ":"
                + settings.port() + " (is the port in use?)");
    }

    /** Readiness is judged by a connection to the port: another process already on it must not pass for us. */
    private static void requireFree(OrbSettings settings) {
        try (ServerSocket probe = new ServerSocket()) {
            probe.bind(new InetSocketAddress(settings.bindAddress(), settings.port()));
        } catch (IOException e) {
            throw new IllegalStateException("port " + settings.port() + " on " + settings.bindAddress()
                    + " is in use (another naming service?): " + e.getMessage(), e);
        }
    }

    /**
     * A fresh folder for the bindings: hosts register again after a restart. JacORB's NameServer writes its bindings
     * there from a shutdown hook of its own, which no other hook can wait for, so a folder is not removed when its
     * JVM exits but by the next naming service that starts, once the process named in it is gone.
     */
    private static Path stateDirectory() {
        Path parent = Path.of(System.getProperty("java.io.tmpdir"));
        removeLeftovers(parent);
        try {
            return Files.createTempDirectory(parent, STATE_PREFIX + ProcessHandle.current().pid() + "-");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot create a folder for the naming service's bindings", e);
        }
    }

    /** Removes the folders of naming services whose process has ended. */
    private static void removeLeftovers(Path parent) {
        try (var dirs = Files.newDirectoryStream(parent, STATE_PREFIX + "*")) {
            for (Path dir : dirs) {
                if (ownerGone(dir.getFileName().toString())) {
                    try (var files = Files.list(dir)) {
                        files.forEach(f -> f.toFile().delete());
                    }
                    Files.deleteIfExists(dir);
                }
            }
        } catch (IOException e) {
            LOG.debug("could not remove old naming service folders in {}: {}", parent, e.toString());
        }
    }

    private static boolean ownerGone(String folderName) {
        String rest = folderName.substring(STATE_PREFIX.length());
        int dash = rest.indexOf('-');
        if (dash <= 0) {
            return false; // not one of ours
        }
        try {
            return ProcessHandle.of(Long.parseLong(rest.substring(0, dash))).map(p -> !p.isAlive()).orElse(true);
        } catch (NumberFormatException e) {
            return false;
        }
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

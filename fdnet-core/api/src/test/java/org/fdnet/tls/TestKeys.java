package org.fdnet.tls;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;

/**
 * Two networks' key files for tests, made once per build under {@code target/test-tls} (keytool takes seconds): the
 * network the processes under test belong to, and a foreign one whose certificates they must refuse.
 */
public final class TestKeys {
    private static final Path ROOT = Path.of("target", "test-tls").toAbsolutePath();

    private TestKeys() {
    }

    /** {@code NAME.p12} of the network under test, made when first asked for. */
    public static synchronized Path network(String name) {
        return make("network", List.of(name)).store(name);
    }

    /** A certificate of another network (its own CA): {@code intruder}. */
    public static synchronized Path foreign() {
        return make("foreign", List.of("intruder")).store("intruder");
    }

    /**
     * The folder of a network whose {@code permissions} file is {@code permissions}, signed by its CA, with a
     * {@code NAME.p12} for each of {@code names}; made when first asked for (each test names its own folder).
     */
    public static synchronized Path withPermissions(String folder, String permissions, List<String> names) {
        KeyMaker maker = make(folder, names);
        Path dir = ROOT.resolve(folder);
        try {
            Files.writeString(dir.resolve(PermissionsFile.FILE), permissions, StandardCharsets.UTF_8);
            maker.signPermissions();
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        return dir;
    }

    private static KeyMaker make(String folder, List<String> names) {
        KeyMaker maker = new KeyMaker(ROOT.resolve(folder));
        try {
            maker.make(names);
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException("interrupted while making test keys", e);
        }
        return maker;
    }
}

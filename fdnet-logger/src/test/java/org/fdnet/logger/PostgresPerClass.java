package org.fdnet.logger;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Comparator;
import java.util.stream.Stream;
import org.junit.jupiter.api.extension.AfterAllCallback;
import org.junit.jupiter.api.extension.BeforeAllCallback;
import org.junit.jupiter.api.extension.ExtensionContext;

/**
 * One {@link PostgresFixture} for a test class: started before its first test, closed (and its folder
 * deleted) after its last. Register it as {@code @RegisterExtension static final PostgresPerClass pg}.
 */
public final class PostgresPerClass implements BeforeAllCallback, AfterAllCallback {
    private Path folder;
    private PostgresFixture fixture;

    @Override
    public void beforeAll(ExtensionContext context) throws Exception {
        folder = Files.createTempDirectory("fdnet-pg-test");
        fixture = new PostgresFixture(folder);
    }

    @Override
    public void afterAll(ExtensionContext context) throws Exception {
        try {
            if (fixture != null) {
                fixture.close();
            }
        } finally {
            deleteTree(folder);
        }
    }

    /** The running fixture (valid between the class's first and last test). */
    public PostgresFixture fixture() {
        return fixture;
    }

    private static void deleteTree(Path root) throws IOException {
        if (root == null || !Files.exists(root)) {
            return;
        }
        try (Stream<Path> paths = Files.walk(root)) {
            for (Path p : (Iterable<Path>) paths.sorted(Comparator.reverseOrder())::iterator) {
                Files.deleteIfExists(p);
            }
        }
    }
}

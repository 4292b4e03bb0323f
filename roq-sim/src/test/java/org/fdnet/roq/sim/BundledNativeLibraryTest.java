package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class BundledNativeLibraryTest {
    @TempDir
    Path cache;

    @AfterEach
    void forgetTheCache() {
        System.clearProperty(BundledNativeLibrary.CACHE_PROPERTY);
    }

    @Test
    void shouldExtractTheLibraryTheBuildBundledByteForByteAndReuseIt() throws Exception {
        System.setProperty(BundledNativeLibrary.CACHE_PROPERTY, cache.toString());

        Path first = BundledNativeLibrary.extracted().orElseThrow();
        Path built = Path.of("target", "native", RoqNativeLibrary.LIBRARY_FILE);

        assertThat(first).startsWith(cache);
        assertThat(Files.readAllBytes(first)).isEqualTo(Files.readAllBytes(built));
        long written = Files.getLastModifiedTime(first).toMillis();
        Thread.sleep(20);
        assertThat(BundledNativeLibrary.extracted()).contains(first);
        assertThat(Files.getLastModifiedTime(first).toMillis()).isEqualTo(written);
        try (var leftovers = Files.list(first.getParent())) {
            assertThat(leftovers).containsExactly(first);
        }
    }
}

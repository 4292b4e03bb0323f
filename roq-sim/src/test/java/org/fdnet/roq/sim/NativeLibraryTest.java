package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** The loader says what is missing and the one command that fixes it. */
class NativeLibraryTest {
    @Test
    void shouldNameTheMissingLibraryAndHowToBuildIt() {
        Path missing = Path.of("/nonexistent/roq/libroqsim.so");
        assertThatThrownBy(() -> RoqNativeLibrary.ensureLoaded(missing))
                .isInstanceOf(NativeLibraryUnavailableException.class)
                .hasMessageContaining(missing.toString())
                .hasMessageContaining("mvn -B -pl roq-sim -am -DskipTests package");
    }

    @Test
    void shouldNameGccAndLibmujocoWhenTheyAreMissing() {
        String message = RoqNativeLibrary.missingMessage(Path.of("/x/libroqsim.so"), false, false);
        assertThat(message).contains("gcc (not on the PATH)").contains("libmujoco-dev")
                .contains(RoqNativeLibrary.INSTALL_COMMAND);
        assertThat(RoqNativeLibrary.missingMessage(Path.of("/x/libroqsim.so"), true, false))
                .doesNotContain("gcc (").contains("libmujoco-dev (no /usr/include/mujoco/mujoco.h)");
    }

    @Test
    void shouldLoadTheBuiltLibraryAndPassTheHandshake() {
        RoqNativeLibrary.ensureLoaded();
        assertThat(RoqNativeLibrary.loadedLibrary()).isNotNull();
        assertThat(RoqNative.abiVersion()).isEqualTo(SharedBlockLayout.VERSION);
        assertThat(RoqNative.blockSize()).isEqualTo(SharedBlockLayout.BLOCK_SIZE);
    }
}

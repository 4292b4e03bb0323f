package org.fdnet.testing;

import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.nio.file.Path;
import org.junit.jupiter.api.Test;

/** Without Xvfb and without the right to install it, a GUI test fails with the one line to run — never a skip. */
class XvfbInstallerTest {
    @Test
    void shouldFailWithTheInstallLineWhenNotRoot() {
        assertThatThrownBy(() -> XvfbInstaller.install(false, Path.of("/usr/bin/apt-get")))
                .isInstanceOf(AssertionError.class)
                .hasMessageContaining("Xvfb is not installed")
                .hasMessageEndingWith("install it with: sudo apt-get install -y --no-install-recommends xvfb xauth");
    }

    @Test
    void shouldFailWithTheInstallLineWithoutAptGet() {
        assertThatThrownBy(() -> XvfbInstaller.install(true, null)).isInstanceOf(AssertionError.class)
                .hasMessageEndingWith("install it with: sudo apt-get install -y --no-install-recommends xvfb xauth");
    }
}

package org.fdnet.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fdnet.testing.CliRun;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * The network `fdnet new nodes` writes (fdnet-core/archetype's template, its package filled in as archetype:generate
 * does) is valid against the DTDs, and its layout names only nodes the network has. The archetype's integration test
 * runs it; this catches a broken file without a Maven-in-Maven build.
 */
class StarterNetworkTest {
    private static final Path TEMPLATE = Path.of("archetype/src/main/resources/archetype-resources/networks");

    @TempDir
    Path dir;

    @Test
    void shouldBeAValidNetworkWithAValidLayoutOnceItsPackageIsFilledIn() throws Exception {
        String network = Files.readString(TEMPLATE.resolve("lab-walk.fdn"), StandardCharsets.UTF_8);
        assertThat(network).contains("${package}.PitchDamper", "${package}.FootCorrection");
        Path fdn = dir.resolve("lab-walk.fdn");
        Files.writeString(fdn, network.replace("${package}", "org.example.lab"), StandardCharsets.UTF_8);
        Path fdg = Files.copy(TEMPLATE.resolve("lab-walk.fdg"), dir.resolve("lab-walk.fdg"));

        CliRun cli = new CliRun();
        assertThat(cli.fdnet("validate", fdn.toString(), fdg.toString())).as(cli.output()).isZero();
        assertThat(cli.output()).contains("lab-walk.fdn: valid (7 modules").contains("lab-walk.fdg: valid")
                .doesNotContain("warning");
    }
}

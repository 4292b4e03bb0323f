package org.fdnet.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import org.fdnet.testing.CliRun;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

class CoreCommandsTest {
    @TempDir
    Path dir;

    private final CliRun cli = new CliRun();

    private int fdnet(String... args) {
        return cli.fdnet(args);
    }

    private Path write(String name, String text) throws Exception {
        Path file = dir.resolve(name);
        Files.writeString(file, text, StandardCharsets.UTF_8);
        return file;
    }

    @Test
    void validateShouldAcceptValidFilesWithExitZero() {
        assertThat(fdnet("validate", "../networks/arms.fdn", "../networks/arms.fdg")).isZero();
        assertThat(cli.output()).contains("arms.fdn: valid (3 modules, 6 Datas").contains("arms.fdg: valid");
    }

    @Test
    void validateShouldPrintOneFileLineColumnLinePerProblemAndExitOne() throws Exception {
        Path bad = write("bad.fdn", "<?xml version=\"1.0\"?>\n<cnet>\n<robot/>\n<module name=\"A\" loadatstart=\"maybe\"/>\n</cnet>\n");
        assertThat(fdnet("validate", "../networks/arms.fdn", bad.toString())).isEqualTo(1);
        String[] lines = cli.output().strip().split("\n");
        assertThat(lines[0]).contains("arms.fdn: valid");
        for (int i = 1; i < lines.length; i++) {
            assertThat(lines[i]).startsWith(bad + ":").matches(".+\\.fdn:\\d+:\\d+: .+");
        }
        assertThat(cli.output()).contains(bad + ":3:").contains(bad + ":4:");
    }

    @Test
    void validateShouldNameAMissingFile() {
        assertThat(fdnet("validate", "-q", dir.resolve("nope.fdn").toString())).isEqualTo(1);
        assertThat(cli.output().strip()).endsWith("nope.fdn: no such file");
    }

    @Test
    void infoShouldCountPerModule() {
        assertThat(fdnet("info", "../networks/arms.fdn")).isZero();
        assertThat(cli.output()).containsPattern("LeftArm\\s+start\\s+2\\s+2\\s+3\\s+2")
                .containsPattern("RightArm\\s+later\\s+2\\s+3\\s+4\\s+2");
    }

    @Test
    void fmtShouldRewriteToCanonicalFormAndCheckShouldThenPass() throws Exception {
        Path messy = write("messy.fdn", "<?xml version=\"1.0\"?>\n<!-- header kept -->\n<cnet name=\"m\"><dstructure><name>D</name>"
                + "<host>h</host><path></path><class>C</class></dstructure></cnet>");
        assertThat(fdnet("fmt", "--check", messy.toString())).isEqualTo(1);
        assertThat(fdnet("fmt", messy.toString())).isZero();
        assertThat(Files.readString(messy)).startsWith("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!DOCTYPE cnet SYSTEM \"cnet.dtd\">\n"
                + "<!-- header kept -->\n<cnet name=\"m\">\n    <dstructure>\n");
        assertThat(fdnet("fmt", "--check", messy.toString())).isZero();
    }

    @Test
    void fmtShouldLeaveAnInvalidFileUntouched() throws Exception {
        String text = "<cnet><robot/></cnet>";
        Path bad = write("bad.fdn", text);
        assertThat(fdnet("fmt", bad.toString())).isEqualTo(1);
        assertThat(Files.readString(bad)).isEqualTo(text);
    }

    @Test
    void everyCommandShouldOfferHelp() {
        for (String command : new String[] {"validate", "info", "fmt", "bench"}) {
            cli.clear();
            assertThat(fdnet(command, "--help")).isZero();
            assertThat(cli.output()).contains("Usage: fdnet " + command);
        }
    }

    @Test
    void theCoreAloneShouldCarryNoBenchmark() {
        // the benchmarks are the bench modules' (fdnet-core/bench, ...), none of which fdnet-core's tests see
        assertThat(FdnetCommand.commandLine().getSubcommands().get("bench").getSubcommands()).isEmpty();
    }

    @Test
    void theExampleNetworksShouldBeInCanonicalForm() {
        assertThat(fdnet("fmt", "--check", "../networks/arms.fdn")).isZero();
    }

    @Test
    void infoShouldListNestedModulesByPathWithWhenEachLoads() {
        assertThat(fdnet("info", "../networks/nested-arm.fdn")).isZero();
        assertThat(cli.output()).containsPattern("Arm/Hand\\s+start")
                .containsPattern("Arm/Hand/Fingers\\s+later").contains("5 modules");
        assertThat(fdnet("validate", "../networks/nested-arm.fdn", "../networks/nested-arm.fdg")).isZero();
    }

    @Test
    void infoWithParamsShouldListEveryDeclaredParameterWithItsDescription() {
        assertThat(fdnet("info", "--params", "../networks/arms.fdn")).isZero();
        assertThat(cli.output()).contains("Relation main/Heartbeat (org.fdnet.runtime.library.PeriodicSource)")
                .containsPattern("period\\s+20\\s+a whole number above 0 ms; required; may change while running")
                .containsPattern("frequency\\s+0.5\\s+a number \\(Hz\\); default 1;")
                .contains("the signal's frequency");
    }

    @Test
    void infoWithParamsShouldShowAParameterTheClassDoesNotDeclareAndAClassItCannotFind() throws Exception {
        Path file = write("odd.fdn", """
                <?xml version="1.0" encoding="UTF-8"?>
                <!DOCTYPE cnet SYSTEM "cnet.dtd">
                <cnet name="odd">
                    <pstructure><name>Smooth</name><host>localhost</host><path></path>
                        <class>MovingAverage</class><param name="windw">5</param></pstructure>
                    <pstructure><name>Lost</name><host>localhost</host><path></path>
                        <class>org.fdnet.runtime.library.NoSuchRelation</class></pstructure>
                </cnet>
                """);
        assertThat(fdnet("info", "--params", file.toString())).isEqualTo(1);
        assertThat(cli.output()).containsPattern("windw\\s+5\\s+not declared by MovingAverage")
                .contains("Relation main/Lost (org.fdnet.runtime.library.NoSuchRelation)")
                .contains("cannot list its parameters: module 'main', node 'Lost'");
    }
}

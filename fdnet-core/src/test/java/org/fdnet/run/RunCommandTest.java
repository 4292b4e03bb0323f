package org.fdnet.run;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import org.fdnet.testing.CliRun;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

@Timeout(60)
class RunCommandTest {
    @TempDir
    Path dir;

    private final CliRun cli = new CliRun();

    private int fdnet(String... args) {
        return cli.fdnet(args);
    }

    @Test
    void shouldRunRoqMotionAndReportItsValuesEventsAndRelations() {
        assertThat(fdnet("run", "../networks/roq-motion.fdn", "--for", "1500ms", "--set", "Walk/I want to walk=0.5")).isZero();
        String out = cli.output();
        assertThat(out).contains("running: modules [main, Balance, Walk, Integration]")
                .containsPattern("\\[\\s+1\\.\\ds\\] firings [\\d,]+ {2}values [\\d,]+ {2}events [\\d,]+ {2}failed 0")
                .contains("summary of roq-motion")
                .containsPattern("DataValueEvent\\s+[\\d,]+")
                .containsPattern("main/A present posture\\s+[\\d,]{3,}\\s+\\[0\\.\\d+, 0\\.\\d+, 0\\.\\d+, 0\\.\\d+\\]")
                .containsPattern("Walk/I want to walk\\s+2\\s+0\\.5000")
                .containsPattern("Integration/integrate\\s+[\\d,]{3,}\\s+RUNNING")
                .contains("failed Relations: none");
    }

    @Test
    void shouldExitOneAndNameEveryProblemOfABadFile() throws Exception {
        Path bad = Files.writeString(dir.resolve("bad.fdn"), "<?xml version=\"1.0\"?>\n<cnet>\n<robot/>\n</cnet>\n");
        assertThat(fdnet("run", bad.toString(), "--for", "1s")).isEqualTo(1);
        assertThat(cli.output()).contains(bad + ":3:");
    }

    @Test
    void shouldExitOneWhenANodeCannotBeMade() throws Exception {
        Path file = Files.writeString(dir.resolve("unknown.fdn"), "<?xml version=\"1.0\"?>\n<cnet name=\"u\">\n"
                + "<pstructure><name>Mystery</name><host>localhost</host><path></path><class>NoSuchRelation</class></pstructure>\n"
                + "</cnet>\n");
        assertThat(fdnet("run", file.toString(), "--for", "1s")).isEqualTo(1);
        assertThat(cli.output()).contains("the network cannot start")
                .contains("module 'main', node 'Mystery', class 'NoSuchRelation'");
    }

    @Test
    void shouldStartWithAParamItsClassReadsOnlyAtStart() {
        // Integration's 'present' is not declared live: a change of the running node would be refused
        assertThat(fdnet("run", "../networks/roq-motion.fdn", "--for", "800ms",
                "--param", "Integration/integrate:present=main/A present posture")).isZero();
        assertThat(cli.output()).containsPattern("Integration/integrate\\s+[\\d,]+\\s+RUNNING")
                .contains("failed Relations: none");
    }

    @Test
    void shouldExitTwoForAParamOfANodeTheFileDoesNotHave() {
        assertThat(fdnet("run", "../networks/roq-motion.fdn", "--for", "1s", "--param", "Nobody:x=1")).isEqualTo(2);
        assertThat(cli.output()).contains("--param Nobody:x=1: module 'main' has no node named 'Nobody'");
    }

    @Test
    void shouldExitTwoForASetThatDoesNotFit() {
        assertThat(fdnet("run", "../networks/roq-motion.fdn", "--for", "1s", "--set", "A present posture=1 2")).isEqualTo(2);
        assertThat(cli.output()).contains("--set A present posture=1 2").contains("4 are expected");
    }

    @Test
    void shouldExitTwoForALoggerViewerAddressThatIsNotHostAndPort() {
        assertThat(fdnet("run", "../networks/roq-motion.fdn", "--for", "1s", "--logger-viewer", "5556")).isEqualTo(2);
        assertThat(cli.output()).contains("--logger-viewer 5556: expected HOST:PORT");
    }

    @Test
    void shouldTraceEveryEventWithNodeNames() {
        assertThat(fdnet("run", "../networks/roq-motion.fdn", "--for", "300ms", "--trace")).isZero();
        assertThat(cli.output()).contains("trace ").contains("command  load module main")
                .contains("named    #").contains("value    main/Physical information = ")
                .contains("relation Integration/integrate RUNNING");
    }
}

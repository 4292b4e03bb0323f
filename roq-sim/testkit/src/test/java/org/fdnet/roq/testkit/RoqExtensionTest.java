package org.fdnet.roq.testkit;

import static org.assertj.core.api.Assertions.assertThat;
import static org.junit.platform.engine.discovery.DiscoverySelectors.selectClass;

import java.nio.file.Files;
import java.nio.file.Path;
import java.time.Duration;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.BeforeEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import org.junit.platform.engine.TestExecutionResult;
import org.junit.platform.testkit.engine.EngineTestKit;

class RoqExtensionTest {
    @TempDir
    Path evidence;

    @BeforeEach
    void evidenceIntoATemporaryFolder() {
        System.setProperty(FailureEvidence.FOLDER_PROPERTY, evidence.toString());
    }

    @AfterEach
    void forgetIt() {
        System.clearProperty(FailureEvidence.FOLDER_PROPERTY);
    }

    /** Run by EngineTestKit below (Surefire does not run nested classes). */
    @RoqTest
    static class RobotTests {
        static String hash;
        static String exactName;

        @Test
        void walks(@Roq(network = "../../networks/roq-rubble.fdn", course = "rubble:5", noise = 3) SimulatedRoq roq) {
            roq.runFor(Duration.ofSeconds(2));
            hash = roq.stateHash();
            roq.assertThat().noFall();
        }

        @Test
        void readsThePlantExactly(
                @Roq(network = "../../networks/roq-rubble.fdn", sensorNoise = false) SimulatedRoq roq) {
            exactName = roq.name();
        }

        @Test
        void expectsTooMuch(@Roq(network = "../../networks/roq-rubble.fdn", course = "crossing") SimulatedRoq roq) {
            roq.runFor(Duration.ofSeconds(2));
            roq.assertThat().walkedAtLeast(5);
        }
    }

    @Test
    void shouldPassARobotTestAndLeaveEvidenceOfAFailingOneInItsMessage() throws Exception {
        var events = EngineTestKit.engine("junit-jupiter").selectors(selectClass(RobotTests.class)).execute().testEvents();

        events.assertStatistics(s -> s.started(3).succeeded(2).failed(1));
        assertThat(RobotTests.hash).hasSize(16);
        assertThat(RobotTests.exactName).as("@Roq(sensorNoise = false)").isEqualTo("roq-rubble.fdn on flat, noise off");
        Throwable failure = events.failed().list().get(0).getRequiredPayload(TestExecutionResult.class).getThrowable()
                .orElseThrow();
        String message = failure.getMessage();

        assertThat(message).startsWith("roq-rubble.fdn on crossing, noise 1 at t = 2.00 s: walked ")
                .contains("expected at least 5.000 m");
        Matcher picture = Pattern.compile("picture of the robot view: (\\S+\\.png)").matcher(message);
        assertThat(picture.find()).as(message).isTrue();
        Path png = Path.of(picture.group(1));
        assertThat(png).startsWith(evidence).exists();
        assertThat(Files.size(png)).isGreaterThan(10_000);
        Matcher recording = Pattern.compile("recording: run (\\d+) \\(([\\d,]+) events\\)").matcher(message);
        assertThat(recording.find()).as(message).isTrue();
        assertThat(Long.parseLong(recording.group(2).replace(",", ""))).isGreaterThan(1000);
        assertThat(message).contains("bin/fdnet viewer --replay " + recording.group(1))
                .contains("bin/fdnet logger --config " + evidence.resolve("logger").resolve("logger.properties"));
    }
}

package org.fdnet.roq.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fdnet.testing.CliRun;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** {@code fdnet run FILE --sim COURSE}: the core's run command joins the network to RoQ's simulator via roq-sim. */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class RunOnSimulatorTest {
    static final String WALK = Path.of("..", "networks", "roq-walk.fdn").toAbsolutePath().normalize().toString();

    private final CliRun cli = new CliRun();

    @Test
    void shouldDriveTheSimulatorWithTheNetworksCommands() {
        int code = cli.fdnet("run", WALK, "--sim", "flat", "--for", "3s");
        String text = cli.output();
        assertThat(code).as(text).isZero();
        assertThat(text).contains("simulated RoQ on course flat", "simulated RoQ: ");
        Matcher m = Pattern.compile("([\\d,]+) commands applied").matcher(text);
        assertThat(m.find()).as(text).isTrue();
        assertThat(Long.parseLong(m.group(1).replace(",", ""))).as("commands from the network applied by the loop")
                .isGreaterThan(100);
    }

    @Test
    void shouldRefuseAnUnknownCourseNamingIt() {
        int code = cli.fdnet("run", WALK, "--sim", "no-such-course", "--for", "3s");
        assertThat(code).isEqualTo(2);
        assertThat(cli.output()).contains("--sim no-such-course: no-such-course");
    }
}

package org.fdnet.roq.bench;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.ByteArrayOutputStream;
import java.io.PrintStream;
import java.nio.charset.StandardCharsets;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import picocli.CommandLine;

/** {@code fdnet bench roq} refuses a bad option with one line naming it, before any run starts. */
@Timeout(60)
class BenchRoqCommandTest {
    private static final String NETWORK = "../../networks/roq-rubble.fdn";

    @Test
    void shouldRefuseToUnloadAModuleTheNetworkDoesNotHave() {
        String err = refused("--part", "breakthroughs", "--network", NETWORK, "--unload", "Balance,Nope");
        assertThat(err.strip()).isEqualTo("fdnet bench roq: --unload Nope: roq-rubble has no such module to unload");
    }

    @Test
    void shouldRefuseToUnloadTheMainModule() {
        String err = refused("--part", "breakthroughs", "--network", NETWORK, "--unload", "main");
        assertThat(err).contains("--unload main:");
    }

    @Test
    void shouldRefuseUnloadWithAPartThatWouldIgnoreIt() {
        String err = refused("--part", "heading", "--network", NETWORK, "--unload", "Balance");
        assertThat(err.strip()).isEqualTo(
                "fdnet bench roq: --unload applies to --part breakthroughs only, was given with --part heading");
    }

    @Test
    void shouldRefuseARobotTestCourseItCannotReadNamingIt() {
        String err = refused("--part", "a", "--network", NETWORK, "--test-course", "rubble:twelve");
        assertThat(err.strip()).startsWith("fdnet bench roq: course 'rubble:twelve': after 'rubble:' comes a seed");
    }

    @Test
    void shouldRefuseARobotTestOfNoSimulatedTime() {
        String err = refused("--part", "a", "--test-seconds", "0");
        assertThat(err.strip()).isEqualTo("fdnet bench roq: --test-seconds must be at least 1, was 0");
    }

    /** Runs the command with {@code args}, asserts it exits 2, and returns what it wrote to standard error. */
    private static String refused(String... args) {
        ByteArrayOutputStream captured = new ByteArrayOutputStream();
        PrintStream err = System.err;
        int code;
        try {
            System.setErr(new PrintStream(captured, true, StandardCharsets.UTF_8));
            code = new CommandLine(new BenchRoqCommand()).execute(args);
        } finally {
            System.setErr(err);
        }
        assertThat(code).isEqualTo(2);
        return captured.toString(StandardCharsets.UTF_8);
    }
}

package org.fdnet.logger.soak;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.fdnet.cli.FdnetCommand;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code fdnet soak --for 60s}: every process fault kind injected and healed, and no acknowledged value lost or stored twice
 * outside what a host's kill -9 may cost (the command's own verdict and exit code).
 */
@Timeout(value = 400, unit = TimeUnit.SECONDS)
class SoakTest {
    @TempDir
    Path work;

    @Test
    void shouldLoseNoAcknowledgedValueWhileEveryFaultKindIsInjected() {
        StringWriter out = new StringWriter();
        int exit = FdnetCommand.commandLine().setOut(new PrintWriter(out, true)).setErr(new PrintWriter(out, true))
                .execute("soak", "--for", "60s", "--network", "../../networks/two-robots.fdn", "--work", work.toString());
        String report = out.toString();
        assertThat(exit).as(report).isZero();
        for (FaultKind kind : FaultKind.values()) {
            if (!kind.network) { // the network kinds need hosts apart: ApartSoakTest
                assertThat(report).as(report).containsPattern("\\] " + kind + " .* healed in ");
            }
        }
        assertThat(report).containsPattern("main/Seq +\\d+ +\\d+ +\\d+ +0 +0 +0 +\\d+ +0").contains("PASSED");
    }
}

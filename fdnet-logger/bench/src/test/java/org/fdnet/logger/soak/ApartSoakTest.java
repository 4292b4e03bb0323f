package org.fdnet.logger.soak;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fdnet.cli.FdnetCommand;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code fdnet soak --apart}: every process on a host of its own (network namespaces; root only — without root the
 * soak fails with the one line that says so, and so does this test), silent network faults on their links, and for
 * each fault: detected and re-wired within the stated bounds, no call blocking a link's caller longer than the call
 * timeout, no Relation stalled longer than its link lets it wait, bounded link rings and logger memory, nothing
 * dropped, and every acknowledged value stored exactly once (the command's own verdict, and its report read here).
 */
class ApartSoakTest {
    private static final Pattern FAULT_LINE = Pattern.compile("\\] (\\w+) +(.+?) +(\\d+) s  detected (\\S+(?: ms)?)"
            + "  re-wired (\\S+(?: ms)?)  healed (\\S+ ms)  call +([\\d,]+) ms  stall +([\\d,]+) ms  held ([\\d,]+) values,"
            + " ([\\d,]+) events, journal ([\\d,]+); dropped 0 values, 0 events  ok");

    @TempDir
    Path work;

    @Test
    @Timeout(value = 420, unit = TimeUnit.SECONDS)
    void shouldSurviveEverySilentNetworkFaultKindWithNoAcknowledgedValueLost() {
        String report = soak("--for", "60s");
        for (FaultKind kind : List.of(FaultKind.HOST_PARTITION, FaultKind.LOGGER_PARTITION, FaultKind.NAMING_PARTITION,
                FaultKind.THROTTLE, FaultKind.LOSS)) {
            assertThat(faultLines(report, kind)).as(report).hasSize(1);
        }
        assertPassed(report);
    }

    @Test
    @Timeout(value = 420, unit = TimeUnit.SECONDS)
    void shouldDetectAndRewireAHostBlackHoledForThirtySeconds() {
        String report = soak("--cycles", "partition30", "--for", "60s");
        List<Matcher> partitions = faultLines(report, FaultKind.HOST_PARTITION);
        assertThat(partitions).as(report).hasSize(1);
        assertThat(partitions.get(0).group(3)).as(report).isEqualTo("30");
        assertPassed(report);
    }

    private String soak(String... options) {
        StringWriter out = new StringWriter();
        String[] args = new String[options.length + 6];
        args[0] = "soak";
        args[1] = "--apart";
        System.arraycopy(options, 0, args, 2, options.length);
        args[options.length + 2] = "--network";
        args[options.length + 3] = "../../networks/two-robots.fdn";
        args[options.length + 4] = "--work";
        args[options.length + 5] = work.toString();
        int exit = FdnetCommand.commandLine().setOut(new PrintWriter(out, true)).setErr(new PrintWriter(out, true))
                .execute(args);
        String report = out.toString();
        assertThat(exit).as(report).isZero();
        return report;
    }

    /** The report's lines of {@code kind}'s network faults whose every measure kept its bound ("ok"). */
    private static List<Matcher> faultLines(String report, FaultKind kind) {
        return report.lines().map(FAULT_LINE::matcher).filter(Matcher::find).filter(m -> m.group(1).equals(kind.name()))
                .toList();
    }

    private static void assertPassed(String report) {
        assertThat(report).as(report).doesNotContain("OVER A BOUND")
                .containsPattern("main/Seq +\\d+ +\\d+ +\\d+ +0 +0 +0 +\\d+ +0")
                .containsPattern("main/Echo +- +\\d+ +\\d+ +0 +0 +0 +\\d+ +0")
                .contains("PASSED");
        for (String line : report.lines().filter(l -> l.contains(" detected ")).toList()) {
            if (line.contains("HOST_PARTITION") || line.contains("LOGGER_PARTITION")) {
                assertThat(line).as("a partition of a host or the logger is detected and re-wired: " + line)
                        .doesNotContain("detected -").doesNotContain("re-wired -");
            }
        }
    }
}

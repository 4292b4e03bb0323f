package org.fdnet.testing;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.ExtendWith;

/** The visibility check finds a field past the window's edge and a cut label on a tab that is not shown first. */
@ExtendWith(RealDisplayExtension.class)
@Timeout(value = 60, unit = TimeUnit.SECONDS)
class WindowVisibilityTest {
    @Test
    void shouldReportAFieldOutsideTheWindowAndACutLabelOnAHiddenTab(RealDisplay display) throws Exception {
        String out = run(display, "broken");
        assertThat(out).contains("DONE");
        assertThat(out.lines().filter(l -> l.startsWith("PROBLEM")).toList()).as(out).hasSize(2)
                .anyMatch(l -> l.contains("tab 'second'") && l.contains("'outside'") && l.contains("outside the window"))
                .anyMatch(l -> l.contains("tab 'second'") && l.contains("'cut'") && l.contains("text cut"));
    }

    @Test
    void shouldFindNothingInAWindowWhereEverythingFits(RealDisplay display) throws Exception {
        String out = run(display, "fixed");
        assertThat(out).contains("DONE").doesNotContain("PROBLEM");
    }

    private static String run(RealDisplay display, String variant) throws Exception {
        Process p = display.java(WindowVisibilityScenario.class, variant).redirectErrorStream(true).start();
        try {
            assertThat(p.waitFor(40, TimeUnit.SECONDS)).isTrue();
            return new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        } finally {
            if (p.isAlive()) {
                p.destroyForcibly();
            }
        }
    }
}

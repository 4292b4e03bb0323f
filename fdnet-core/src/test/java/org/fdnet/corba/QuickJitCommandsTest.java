package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import org.junit.jupiter.api.Test;

/** Which commands stop their JIT at C1: the short ones, matched by their first words. */
class QuickJitCommandsTest {
    @Test
    void shouldStopTheJitAtC1ForShortCommandsWhateverTheirArguments() {
        assertThat(QuickJitCommands.matches(List.of("validate", "a.fdn", "b.fdn"))).isTrue();
        assertThat(QuickJitCommands.matches(List.of("--version"))).isTrue();
        assertThat(QuickJitCommands.matches(List.of("bench", "load", "cold-probe", "--bare", "x.fdn"))).isTrue();
    }

    @Test
    void shouldKeepTieredCompilationForLongRunsAndForAPrefixOfAListedCommand() {
        assertThat(QuickJitCommands.matches(List.of("run", "a.fdn"))).isFalse();
        assertThat(QuickJitCommands.matches(List.of("bench", "load"))).as("bench load itself measures warm code too").isFalse();
        assertThat(QuickJitCommands.matches(List.of("bench"))).isFalse();
        assertThat(QuickJitCommands.matches(List.of("logger"))).isFalse();
        assertThat(QuickJitCommands.matches(List.of())).isFalse();
    }
}

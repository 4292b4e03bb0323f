package org.fdnet.cli;

import static org.assertj.core.api.Assertions.assertThat;

import org.junit.jupiter.api.Test;
import picocli.CommandLine;

/**
 * With every module on the class path (what bin/fdnet runs), each part's commands and each bench module's benchmarks
 * arrive through CommandProvider; BenchCommand itself names none.
 */
class WholeCommandTreeTest {
    private final CommandLine fdnet = FdnetCommand.commandLine();

    @Test
    void shouldOfferEveryPartsCommands() {
        assertThat(fdnet.getSubcommands()).containsKeys("validate", "info", "fmt", "keys", "run", "naming", "host",
                "control", "logger", "export", "viewer", "hi", "sim", "demo", "soak", "bench", "sdk", "new", "apart");
        assertThat(fdnet.getSubcommands().get("sdk").getSubcommands()).containsKey("install");
        assertThat(fdnet.getSubcommands().get("new").getSubcommands()).containsKey("nodes");
        assertThat(fdnet.getSubcommands().get("apart").getSubcommands())
                .containsOnlyKeys("up", "exec", "fault", "status", "down", "sweep");
    }

    @Test
    void shouldOfferEveryBenchModulesBenchmarks() {
        assertThat(fdnet.getSubcommands().get("bench").getSubcommands())
                .containsOnlyKeys("load", "core", "corba", "logger", "export", "viewer", "hi", "rt", "sim", "roq", "report");
    }
}

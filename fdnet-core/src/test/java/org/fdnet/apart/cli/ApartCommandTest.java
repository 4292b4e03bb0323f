package org.fdnet.apart.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fdnet.apart.ApartRig;
import org.fdnet.cli.FdnetCommand;
import org.fdnet.corba.FdnetChildProcess;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import picocli.CommandLine;

/**
 * {@code fdnet apart} as a person uses it: {@code up} in one process, {@code fault}, {@code status} and {@code exec}
 * from another; the rig goes when {@code up} is stopped, and what a killed {@code up} left is swept (needs root).
 */
@Timeout(value = 180, unit = TimeUnit.SECONDS)
class ApartCommandTest {
    private static final String NAME = "fdnrigcli";

    private final List<FdnetChildProcess> processes = new ArrayList<>();

    @AfterEach
    void cleanUp() {
        processes.forEach(FdnetChildProcess::close);
        ApartRig.sweep(NAME);
    }

    @Test
    void shouldPutFaultsOnTheRigThatIsUpAndRemoveItWhenUpIsStopped() {
        FdnetChildProcess up = up();
        assertThat(up.output()).anyMatch(l -> l.matches("\\s+flyer\\s+10\\.231\\.\\d+\\.2\\s+" + NAME + "-\\d+-flyer\\s+none"));
        ApartRig rig = ApartRig.find(NAME).orElseThrow();
        assertThat(rig.hosts()).containsExactly("naming", "flyer");
        assertThat(rig.ownerPid()).isEqualTo(up.pid());

        assertThat(fdnet("apart", "fault", "--name", NAME, "flyer", "blackhole")).contains("ok: flyer black-holed");
        assertThat(rig.faultTables("flyer")).containsExactly("fdnet_apart_blackhole");
        assertThat(fdnet("apart", "fault", "--name", NAME, "flyer", "throttle", "500")).contains("ok: flyer throttled");
        assertThat(fdnet("apart", "status", "--name", NAME)).containsPattern("flyer .* blackhole, throttle 500Kbit");
        assertThat(fdnet("apart", "fault", "--name", NAME, "flyer", "loss")).contains("loss needs PERCENT");
        assertThat(fdnet("apart", "fault", "--name", NAME, "rover", "heal")).contains("no host 'rover'");
        assertThat(fdnet("apart", "fault", "--name", NAME, "flyer", "clear")).contains("ok: flyer cleared");
        assertThat(rig.faultTables("flyer")).isEmpty();

        up.stop(30_000);
        assertThat(up.output()).contains("fdnet apart: removed");
        assertThat(ApartRig.find(NAME)).isEmpty();
        assertThat(fdnet("apart", "status", "--name", NAME)).contains("no rig named " + NAME + " is up");
    }

    @Test
    void shouldSweepWhatAKilledUpLeftBehind() {
        FdnetChildProcess up = up();
        String rigNamespace = ApartRig.find(NAME).orElseThrow().rigNamespace();
        up.kill();
        assertThat(ApartRig.find(NAME)).as("a dead process's rig is not up").isEmpty();
        assertThat(fdnet("apart", "sweep", "--name", NAME)).contains("removed " + rigNamespace + "-naming")
                .contains(rigNamespace + "-flyer").contains(rigNamespace);
        assertThat(fdnet("apart", "sweep", "--name", NAME)).contains("nothing left behind");
    }

    private FdnetChildProcess up() {
        FdnetChildProcess up = FdnetChildProcess.start("apart up", List.of("apart", "up", "--name", NAME, "--hosts",
                "naming,flyer"), "fdnet apart up ready", 90_000);
        processes.add(up);
        return up;
    }

    /** Runs {@code fdnet ARGS} in this JVM; what it printed on both streams. */
    private static String fdnet(String... args) {
        StringWriter out = new StringWriter();
        CommandLine cli = FdnetCommand.commandLine().setOut(new PrintWriter(out, true)).setErr(new PrintWriter(out, true));
        cli.execute(args);
        return out.toString();
    }
}

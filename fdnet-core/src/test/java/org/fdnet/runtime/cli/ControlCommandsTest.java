package org.fdnet.runtime.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Path;
import java.util.List;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.runtime.loading.ClassLoadingPolicy;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** fdnet run's standard-input commands on a single-host run: the local Controller is the NetworkControl. */
@Timeout(60)
class ControlCommandsTest {
    private static final Path FILE = Path.of("../networks/roq-motion.fdn");

    @Test
    void shouldExecuteEachCommandOnTheLocalControllerOrAnswerWhyNot() throws Exception {
        RuntimeOptions o = RuntimeOptions.defaults().classLoading(ClassLoadingPolicy.forNetworkFile(FILE, List.of()));
        try (RuntimeNetwork net = RuntimeNetwork.start(NetworkRepository.load(FILE), o)) {
            Controller c = net.controller();
            ControlCommands commands = new ControlCommands(c, new PrintWriter(new StringWriter()));

            assertThat(commands.execute("hold Balance")).startsWith("ok: ");
            assertThat(c.heldModules()).containsExactly("Balance");
            assertThat(commands.execute("resume Balance")).startsWith("ok: ");
            assertThat(c.heldModules()).isEmpty();

            assertThat(commands.execute("unload Walk")).startsWith("ok: ");
            assertThat(c.loadedModules()).doesNotContain("Walk");
            assertThat(commands.execute("load Walk")).startsWith("ok: ");
            assertThat(c.loadedModules()).contains("Walk");

            assertThat(commands.execute("send Walk/I want to walk=0.25")).startsWith("ok: send Walk/I want to walk=0.25");
            assertThat(c.value(new NodeRef("Walk", "I want to walk")).asDouble()).isEqualTo(0.25);

            assertThat(commands.execute("hold Nowhere")).startsWith("refused: ");
            assertThat(commands.execute("send Nowhere/nothing=1")).startsWith("refused: send Nowhere/nothing=1: ");
            assertThat(commands.execute("set Walk/walk")).startsWith("error: ").contains("[MODULE/]NODE/PARAM=VALUE");
            assertThat(commands.execute("frobnicate Walk")).startsWith("error: unknown command 'frobnicate'");
            assertThat(commands.execute("hold")).startsWith("error: hold needs an argument");
            assertThat(commands.execute("bogus")).startsWith("error: unknown command 'bogus'");
            assertThat(commands.execute("help")).contains("hold MODULE").contains("send [MODULE/]NODE=VALUE");
            assertThat(commands.execute("   ")).isNull();
        }
    }
}

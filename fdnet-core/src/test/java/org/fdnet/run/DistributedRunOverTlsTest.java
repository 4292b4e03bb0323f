package org.fdnet.run;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.tls.TestKeys;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code fdnet run --tls} in a distributed run: the naming service, host {@code flyer} and the run, each a child process
 * with its own certificate of one network, speak mutual TLS only, and the run's Operator gets the flyer's values.
 */
@Timeout(value = 150, unit = TimeUnit.SECONDS)
class DistributedRunOverTlsTest {
    private static final String NETWORK = """
            <?xml version="1.0" encoding="UTF-8"?>
            <cnet name="tls-test">
                <dstructure><name>Level</name><host>flyer</host><path></path>
                    <class>org.fdnet.runtime.library.DoubleData</class></dstructure>
                <pstructure><name>Source</name><host>flyer</host><path></path>
                    <class>org.fdnet.runtime.library.Expression</class>
                    <param name="period" type="long">50</param><param name="expression">7</param></pstructure>
                <pstructure><name>Operator</name><host>localhost</host><path></path>
                    <class>org.fdnet.runtime.library.Print</class>
                    <param name="prefix">operator</param><param name="every" type="long">500</param></pstructure>
                <connection>
                    <write><data>Level</data><proc>Source</proc></write>
                    <read><data>Level</data><proc>Operator</proc></read>
                </connection>
            </cnet>
            """;

    @TempDir
    Path folder;

    private final List<FdnetChildProcess> processes = new ArrayList<>();

    @AfterEach
    void stopEveryProcess() {
        for (int i = processes.size() - 1; i >= 0; i--) {
            processes.get(i).close();
        }
    }

    @Test
    void shouldRunAcrossHostsOverMutualTls() throws Exception {
        Path file = Files.writeString(folder.resolve("tls-test.fdn"), NETWORK);
        int port = FdnetChildProcess.freePort();
        String naming = "corbaloc::127.0.0.1:" + port + "/NameService";
        start("naming", List.of("naming", "--port", Integer.toString(port), "--tls",
                TestKeys.network("naming").toString()), "fdnet naming ready");
        FdnetChildProcess flyer = start("host flyer", List.of("host", "--name", "flyer", "--naming", naming, "--tls",
                TestKeys.network("flyer").toString()), "fdnet host flyer ready");
        FdnetChildProcess run = start("run", List.of("run", file.toString(), "--naming", naming, "--for", "12s",
                "--tls", TestKeys.network("station").toString()), "running on 2 hosts");

        // 12 s: the first value waits for the flyer's TLS connection to the run's host (about 3 s on a loaded machine)
        assertThat(run.awaitExit(60_000)).as(String.join("\n", run.output())).isZero();
        assertThat(run.output()).as(String.join("\n", run.output()) + "\nFLYER:\n" + String.join("\n", flyer.output()))
                .anyMatch(l -> l.startsWith("[operator]") && l.contains("main/Level=7.0000"));
    }

    private FdnetChildProcess start(String label, List<String> args, String ready) {
        FdnetChildProcess p = FdnetChildProcess.start(label, args, ready, 60_000);
        processes.add(p);
        return p;
    }
}

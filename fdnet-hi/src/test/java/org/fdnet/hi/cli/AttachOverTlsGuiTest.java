package org.fdnet.hi.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fdnet.cli.FdnetCommand;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.testing.RealDisplay;
import org.fdnet.testing.RealDisplayExtension;
import org.fdnet.tls.TestKeys;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.extension.ExtendWith;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code fdnet hi --attach NAME --tls FILE} on a real X display (Xvfb in CI): a network run across hosts whose
 * processes speak mutual TLS only is attached to with a certificate of that network (and the editor's window
 * rendered); without one the attach is refused; a key store that does not exist is named.
 */
@ExtendWith(RealDisplayExtension.class)
@Timeout(value = 240, unit = TimeUnit.SECONDS)
class AttachOverTlsGuiTest {
    private static final String NETWORK = """
            <?xml version="1.0" encoding="UTF-8"?>
            <cnet name="tls-attach">
                <dstructure><name>Level</name><host>flyer</host><path></path>
                    <class>org.fdnet.runtime.library.DoubleData</class></dstructure>
                <pstructure><name>Source</name><host>flyer</host><path></path>
                    <class>org.fdnet.runtime.library.Expression</class>
                    <param name="period" type="long">100</param><param name="expression">t</param></pstructure>
                <pstructure><name>Operator</name><host>localhost</host><path></path>
                    <class>org.fdnet.runtime.library.Print</class>
                    <param name="prefix">operator</param><param name="every" type="long">1000</param></pstructure>
                <connection>
                    <write><data>Level</data><proc>Source</proc></write>
                    <read><data>Level</data><proc>Operator</proc></read>
                </connection>
            </cnet>
            """;

    @TempDir
    Path dir;

    private final List<FdnetChildProcess> processes = new ArrayList<>();

    @AfterEach
    void stopEveryProcess() {
        for (int i = processes.size() - 1; i >= 0; i--) {
            processes.get(i).close();
        }
    }

    @Test
    void shouldAttachToARunOverMutualTlsWithTheNetworksCertificateOnly(RealDisplay display) throws Exception {
        Path file = Files.writeString(dir.resolve("tls-attach.fdn"), NETWORK);
        int port = FdnetChildProcess.freePort();
        String naming = "corbaloc::127.0.0.1:" + port + "/NameService";
        start("naming", List.of("naming", "--port", Integer.toString(port), "--tls",
                TestKeys.network("naming").toString()), "fdnet naming ready");
        start("host flyer", List.of("host", "--name", "flyer", "--naming", naming, "--tls",
                TestKeys.network("flyer").toString()), "fdnet host flyer ready");
        start("run", List.of("run", file.toString(), "--naming", naming, "--for", "120s", "--tls",
                TestKeys.network("station").toString()), "control object of tls-attach");

        Path png = dir.resolve("attached.png");
        Finished attached = hi(display, "--attach", "tls-attach", "--naming", naming, "--tls",
                TestKeys.network("editor").toString(), "--screenshot", png.toString());
        assertThat(attached.exit).as(attached.output).isZero();
        assertThat(attached.output).contains("wrote " + png);
        assertThat(Files.size(png)).isPositive();

        Finished plain = hi(display, "--attach", "tls-attach", "--naming", naming, "--screenshot",
                dir.resolve("plain.png").toString());
        assertThat(plain.exit).as(plain.output).isEqualTo(1);
        assertThat(plain.output).contains("fdnet hi --attach tls-attach: ");

        Finished missing = hi(display, "--attach", "tls-attach", "--tls", dir.resolve("none.p12").toString());
        assertThat(missing.exit).as(missing.output).isEqualTo(2);
        assertThat(missing.output).contains("fdnet hi: --tls: ").contains("none.p12");
    }

    private record Finished(int exit, String output) {
    }

    private Finished hi(RealDisplay display, String... args) throws Exception {
        List<String> all = new ArrayList<>(List.of("hi"));
        all.addAll(List.of(args));
        Path log = Files.createTempFile(dir, "hi", ".log");
        Process p = display.java(FdnetCommand.class, all.toArray(String[]::new)).redirectErrorStream(true)
                .redirectOutput(log.toFile()).start();
        try {
            boolean ended = p.waitFor(90, TimeUnit.SECONDS);
            String output = Files.readString(log, StandardCharsets.UTF_8);
            assertThat(ended).as("fdnet hi ended within 90 s; output:%n%s", output).isTrue();
            return new Finished(p.exitValue(), output);
        } finally {
            p.destroyForcibly();
        }
    }

    private void start(String label, List<String> args, String ready) {
        processes.add(FdnetChildProcess.start(label, args, ready, 90_000));
    }
}

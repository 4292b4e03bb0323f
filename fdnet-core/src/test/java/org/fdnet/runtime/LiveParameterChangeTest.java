package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;
import static org.fdnet.runtime.TestNetworks.*;

import java.nio.file.Files;
import java.nio.file.Path;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeStartException;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** Declared parameters in a running network: live ones change, the others are refused; bad ones never start. */
@Timeout(30)
class LiveParameterChangeTest {
    @TempDir
    Path dir;

    private static NetworkInfo network() {
        NetworkInfo n = new NetworkInfo("pick");
        n.addNode("main", data("Index", "DoubleData"));
        n.addNode("main", data("Choice", "DoubleData"));
        n.addNode("main", data("Out", "BooleanData"));
        n.addNode("main", relation("Pick", "Selector", "select=Index"));
        n.addNode("main", relation("Switch", "Threshold", "high=2"));
        read(n, "main", "Index", "Pick");
        read(n, "main", "Choice", "Pick");
        write(n, "main", "Pick", "Out");
        read(n, "main", "Choice", "Switch");
        return n;
    }

    @Test
    void shouldApplyAChangeOfALiveParameter() throws Exception {
        try (RuntimeNetwork net = start(network(), null)) {
            ChangeOutcome outcome = net.controller().setParameter(ref("Switch"), "high", "3");
            assertThat(outcome.executed()).as(outcome.reason()).isTrue();
            assertThat(net.controller().snapshot().node(ref("Switch")).parameters().get(0).value()).isEqualTo("3");
        }
    }

    @Test
    void shouldRefuseAChangeOfAParameterNotDeclaredLiveAndKeepTheNodeRunning() throws Exception {
        try (RuntimeNetwork net = start(network(), null)) {
            NetworkInfo before = net.controller().snapshot();
            ChangeOutcome outcome = net.controller().setParameter(ref("Pick"), "select", "Choice");
            assertThat(outcome.executed()).isFalse();
            assertThat(outcome.reason()).isEqualTo("module 'main', node 'Pick': parameter 'select' of Selector is read"
                    + " once at start and cannot change while the network runs; change the file and start it again");
            assertThat(net.controller().snapshot()).isEqualTo(before);
        }
    }

    @Test
    void shouldRefuseToStartAFileWhoseParameterLiesOutsideItsDeclaredRange() throws Exception {
        Path file = dir.resolve("bad.fdn");
        Files.writeString(file, """
                <?xml version="1.0" encoding="UTF-8"?>
                <!DOCTYPE cnet SYSTEM "cnet.dtd">
                <cnet name="bad">
                    <dstructure><name>In</name><host>localhost</host><path></path>
                        <class>org.fdnet.runtime.library.DoubleData</class></dstructure>
                    <dstructure><name>Out</name><host>localhost</host><path></path>
                        <class>org.fdnet.runtime.library.DoubleData</class></dstructure>
                    <pstructure><name>Smooth</name><host>localhost</host><path></path>
                        <class>org.fdnet.runtime.library.MovingAverage</class>
                        <param name="window" type="long">0</param></pstructure>
                    <connection>
                        <read><data>In</data><proc>Smooth</proc></read>
                        <write><data>Out</data><proc>Smooth</proc></write>
                    </connection>
                </cnet>
                """);
        NetworkInfo n = NetworkRepository.load(file);
        assertThatThrownBy(() -> start(n, null)).isInstanceOf(RuntimeStartException.class)
                .hasMessageContaining("module 'main', node 'Smooth': parameter 'window' must be a whole number at least 1"
                        + " values, was 0");
    }
}

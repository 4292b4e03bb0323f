package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.HostHelper;
import org.fdnet.corba.idl.NodeId;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.tls.TestKeys;
import org.fdnet.tls.TlsIdentity;
import org.fdnet.tls.TransportSecurity;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A naming service and a host speaking mutual TLS, as child processes: a client with the network's certificate reads
 * and writes a Data; plain JacORB and a client with another network's certificate reach neither the naming service
 * nor the host (even given the host's reference), and nothing they tried is applied.
 */
@Timeout(value = 180, unit = TimeUnit.SECONDS)
class MutualTlsTest {
    private static final NodeRef CERTAINTY = new NodeRef("main", "Certainty");
    private final List<AutoCloseable> toClose = new ArrayList<>();

    @AfterEach
    void stop() throws Exception {
        for (int i = toClose.size() - 1; i >= 0; i--) {
            toClose.get(i).close();
        }
        TransportSecurity.off();
    }

    @Test
    void shouldServeOnlyClientsWithTheNetworksCertificate() throws Exception {
        int port = FdnetChildProcess.freePort();
        start("naming", List.of("naming", "--port", Integer.toString(port), "--tls", TestKeys.network("naming").toString()),
                "fdnet naming ready");
        String plainNaming = "corbaloc::127.0.0.1:" + port + "/NameService";
        start("flyer", List.of("host", "--name", "flyer", "--naming", plainNaming, "--tls",
                TestKeys.network("flyer").toString()), "fdnet host flyer ready");
        TlsIdentity foreign = TlsIdentity.load(TestKeys.foreign());

        TransportSecurity.use(TlsIdentity.load(TestKeys.network("tester")));
        OrbRuntime member = orb(plainNaming);
        Host flyer = HostDirectory.connect(member).find("flyer").orElseThrow();
        NodeId certainty = IdlMapping.id(CERTAINTY);
        flyer.createNode(IdlMapping.spec("main", NodeInfo.data("Certainty", "DoubleData")));
        flyer.write(certainty, ValueCodec.encode(0.25));
        String flyerReference = member.orb().object_to_string(flyer);

        TransportSecurity.off();
        OrbRuntime plain = orb(plainNaming);
        assertThatThrownBy(() -> HostDirectory.connect(plain).find("flyer"))
                .as("plain JacORB through the naming service").isInstanceOf(RuntimeException.class);
        Host plainFlyer = HostHelper.unchecked_narrow(plain.orb().string_to_object(flyerReference));
        assertThatThrownBy(() -> plainFlyer.write(certainty, ValueCodec.encode(1.0)))
                .as("plain JacORB given the host's reference").isInstanceOf(org.omg.CORBA.SystemException.class);

        TransportSecurity.use(foreign);
        OrbRuntime stranger = orb(plainNaming);
        assertThatThrownBy(() -> HostDirectory.connect(stranger).find("flyer"))
                .as("another network's certificate").isInstanceOf(RuntimeException.class);
        Host strangerFlyer = HostHelper.unchecked_narrow(stranger.orb().string_to_object(flyerReference));
        assertThatThrownBy(() -> strangerFlyer.write(certainty, ValueCodec.encode(1.0)))
                .isInstanceOf(org.omg.CORBA.SystemException.class);

        TransportSecurity.use(TlsIdentity.load(TestKeys.network("tester")));
        assertThat(ValueCodec.decode(flyer.read(certainty))).as("nothing the refused clients sent was applied")
                .isEqualTo(0.25);
        flyer.write(certainty, ValueCodec.encode(0.75));
        assertThat(ValueCodec.decode(flyer.read(certainty))).isEqualTo(0.75);
    }

    private void start(String label, List<String> args, String ready) {
        toClose.add(FdnetChildProcess.start(label, args, ready, 60_000));
    }

    private OrbRuntime orb(String naming) {
        OrbRuntime orb = OrbRuntime.start(OrbSettings.defaults().withNaming(naming).withCallTimeoutMillis(5_000));
        toClose.add(orb);
        return orb;
    }
}

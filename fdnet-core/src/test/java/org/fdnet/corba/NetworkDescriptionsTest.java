package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.Map;
import java.util.Set;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.WholeNetwork;
import org.junit.jupiter.api.Test;

/** A paste travels as the whole definition after it: the trip through the IDL must lose nothing. */
class NetworkDescriptionsTest {
    @Test
    void shouldCarryEveryModuleNodeParameterAndConnectionAttributeThroughTheIdl() throws Exception {
        for (String file : new String[] {"arms.fdn", "two-robots.fdn", "roq-walk.fdn"}) {
            NetworkInfo network = NetworkRepository.load(Path.of("../networks", file));
            Map<NodeRef, String> placed = Map.of(new NodeRef("main", network.main().nodes().iterator().next().name()),
                    "crawler");
            WholeNetwork.Snapshot sent = new WholeNetwork.Snapshot(network, Set.of("main"), placed);

            WholeNetwork.Snapshot received = NetworkDescriptions.decode(NetworkDescriptions.encode(7, sent));

            assertThat(received.definition()).as(file).isEqualTo(network);
            assertThat(received.definition().modules()).extracting(m -> m.name() + ":" + m.loadAtStart())
                    .as(file).containsExactlyElementsOf(network.modules().stream()
                            .map(m -> m.name() + ":" + m.loadAtStart()).toList());
            assertThat(received.loaded()).containsExactly("main");
            assertThat(received.placedOn()).isEqualTo(placed);
        }
        assertThat(NetworkDescriptions.encode(7, new WholeNetwork.Snapshot(new NetworkInfo(null), Set.of(), Map.of()))
                .version).isEqualTo(7);
    }
}

package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.fdnet.corba.idl.ChangeKind;
import org.fdnet.corba.idl.ConnectionSpec;
import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.NetworkChange;
import org.fdnet.corba.idl.NetworkListener;
import org.fdnet.corba.idl.NetworkListenerHelper;
import org.fdnet.corba.idl.NetworkListenerPOA;
import org.fdnet.corba.idl.NodeSpec;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** A remote {@code NetworkListener} hears a host's structural changes. */
@Timeout(value = 90, unit = TimeUnit.SECONDS)
class NetworkListenerTest {
    private CorbaCluster cluster;

    @AfterEach
    void stop() {
        if (cluster != null) {
            cluster.close();
        }
    }

    @Test
    void shouldTellASubscribedListenerAboutModulesNodesAndLinks() throws Exception {
        cluster = CorbaCluster.start();
        Host crawler = cluster.startHost("crawler");
        List<NetworkChange> heard = new CopyOnWriteArrayList<>();
        NetworkListener listener = NetworkListenerHelper.narrow(cluster.orb().activate(new NetworkListenerPOA() {
            @Override
            public void changed(NetworkChange change) {
                heard.add(change);
            }
        }));
        crawler.subscribe(listener);

        NodeRef use = new NodeRef("main", "use");
        NodeRef out = new NodeRef("main", "out");
        crawler.loadModule("main", new NodeSpec[] {
            IdlMapping.spec("main", NodeInfo.relation(use.node(), "Constant", Parameter.named("value", "1"))),
            IdlMapping.spec("main", NodeInfo.data(out.node(), "DoubleData"))},
                new ConnectionSpec[] {IdlMapping.spec(ConnectionInfo.writer(use, out))});
        crawler.unloadModule("main");

        long deadline = System.currentTimeMillis() + 10_000;
        while (heard.size() < 2 && System.currentTimeMillis() < deadline) {
            Thread.sleep(20);
        }
        assertThat(heard).extracting(c -> c.kind).containsExactly(ChangeKind.MODULE_LOADED, ChangeKind.MODULE_UNLOADED);
        assertThat(heard).allSatisfy(c -> assertThat(c.hostName).isEqualTo("crawler"));
        assertThat(heard.get(0).subject).isEqualTo("main (2 nodes, 1 connections)");
        assertThat(crawler.nodes()).isEmpty();
    }
}

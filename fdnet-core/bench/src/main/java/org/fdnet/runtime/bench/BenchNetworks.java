package org.fdnet.runtime.bench;

import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.runtime.engine.RuntimeStartException;
import org.fdnet.runtime.loading.ClassLoadingPolicy;

/** The benchmark's networks, built in code: a chain of n Relays and a fan-out of one Data to n Relays. */
final class BenchNetworks {
    private BenchNetworks() {
    }

    static final String DOUBLE = "org.fdnet.runtime.library.DoubleData";

    static NodeRef ref(String node) {
        return new NodeRef("main", node);
    }

    /** D0 → R1 → D1 → ... → Rn → Dn. */
    static NetworkInfo chain(int relations) {
        NetworkInfo n = new NetworkInfo("chain-" + relations);
        n.addNode("main", NodeInfo.data("D0", DOUBLE));
        for (int i = 1; i <= relations; i++) {
            n.addNode("main", NodeInfo.data("D" + i, DOUBLE));
            n.addNode("main", NodeInfo.relation("R" + i, Relay.class.getName()));
            n.addConnection("main", ConnectionInfo.reader(ref("D" + (i - 1)), ref("R" + i)));
            n.addConnection("main", ConnectionInfo.writer(ref("R" + i), ref("D" + i)));
        }
        return n;
    }

    /** In → R0..R(n-1), each writing its own Out_i. */
    static NetworkInfo fanOut(int relations) {
        NetworkInfo n = new NetworkInfo("fan-out-" + relations);
        n.addNode("main", NodeInfo.data("In", DOUBLE));
        for (int i = 0; i < relations; i++) {
            n.addNode("main", NodeInfo.data("Out" + i, DOUBLE));
            n.addNode("main", NodeInfo.relation("R" + i, Relay.class.getName()));
            n.addConnection("main", ConnectionInfo.reader(ref("In"), ref("R" + i)));
            n.addConnection("main", ConnectionInfo.writer(ref("R" + i), ref("Out" + i)));
        }
        return n;
    }

    static RuntimeNetwork start(NetworkInfo n, RuntimeOptions options) throws RuntimeStartException {
        return RuntimeNetwork.start(n, options.classLoading(
                ClassLoadingPolicy.builtInOnly().withBuiltInPackage("org.fdnet.runtime.bench.")));
    }
}

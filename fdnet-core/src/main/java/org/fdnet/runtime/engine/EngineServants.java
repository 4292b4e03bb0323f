package org.fdnet.runtime.engine;

import java.util.function.BooleanSupplier;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.Servants;
import org.fdnet.runtime.WholeNetwork;

/** Makes the {@link Servants} of one of an engine's Relations from the engine's parts. */
final class EngineServants {
    private EngineServants() {
    }

    /**
     * Servants of Relation {@code self}: its changes name {@code selfId} as their source; with {@code whole} they see
     * and reshape every host's nodes, with {@code null} this engine's only; {@code selfRuns} says whether the Relation
     * instance still runs (its servants go with it).
     */
    static Servants of(RuntimeNetwork network, NodeRef self, int selfId, WholeNetwork whole, BooleanSupplier selfRuns) {
        Controller controller = network.controllerFor(selfId);
        EngineScope engine = new EngineScope(network, controller);
        return new Servants(self, controller, whole == null ? engine : new WholeNetworkScope(engine, whole),
                network.servantRegistry(), selfRuns);
    }
}

package org.fdnet.corba;

import java.util.Map;
import java.util.Optional;
import java.util.concurrent.ConcurrentHashMap;
import org.fdnet.corba.idl.ChangeRequest;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Controller;

/**
 * A host's side of the two-phase live changes ({@code prepareChange}/{@code commitChange}/{@code abortChange}
 * of {@code fdnet.idl}): {@link #prepare} checks a change against this host's engine without touching it and
 * keeps it; {@link #commit} executes it through the engine's {@link Controller}; {@link #abort} forgets it.
 */
final class LiveChanges {
    private final String hostName;
    private final LocalNetwork network;
    private final Map<Long, ChangeRequest> prepared = new ConcurrentHashMap<>();

    LiveChanges(String hostName, LocalNetwork network) {
        this.hostName = hostName;
        this.network = network;
    }

    /** The reason this host cannot execute {@code change} now, or {@code ""}; a possible change is kept. */
    String prepare(ChangeRequest change) {
        Optional<Controller> engine = network.controller();
        if (engine.isEmpty()) {
            return "host " + hostName + " takes no live changes";
        }
        Controller c = engine.get();
        String refusal = switch (change.op.value()) {
            case org.fdnet.corba.idl.ChangeOp._CO_HOLD -> !c.loadedModules().contains(change.moduleName)
                    ? "module " + change.moduleName + " is not loaded on host " + hostName
                    : c.heldModules().contains(change.moduleName)
                    ? "module " + change.moduleName + " is already on hold on host " + hostName : "";
            case org.fdnet.corba.idl.ChangeOp._CO_RESUME -> c.heldModules().contains(change.moduleName) ? ""
                    : "module " + change.moduleName + " is not on hold on host " + hostName;
            case org.fdnet.corba.idl.ChangeOp._CO_SET_PARAMETER, org.fdnet.corba.idl.ChangeOp._CO_SEND ->
                    network.nodes().contains(IdlMapping.ref(change.node)) ? ""
                            : "node " + IdlMapping.ref(change.node) + " does not run on host " + hostName;
            default -> "host " + hostName + " does not know change kind " + change.op.value();
        };
        if (refusal.isEmpty()) {
            prepared.put(change.id, change);
        }
        return refusal;
    }

    /** Executes a prepared change; returns {@code null} when it was executed, else the reason it failed. */
    String commit(long id) {
        ChangeRequest change = prepared.remove(id);
        if (change == null) {
            return "host " + hostName + " has no prepared change " + id;
        }
        Controller c = network.controller().orElseThrow();
        ChangeOutcome outcome = switch (change.op.value()) {
            case org.fdnet.corba.idl.ChangeOp._CO_HOLD -> c.hold(change.moduleName);
            case org.fdnet.corba.idl.ChangeOp._CO_RESUME -> c.resume(change.moduleName);
            case org.fdnet.corba.idl.ChangeOp._CO_SET_PARAMETER ->
                    c.setParameter(IdlMapping.ref(change.node), change.name, change.value);
            default -> c.send(IdlMapping.ref(change.node), change.value);
        };
        return outcome.executed() ? null : "host " + hostName + ": " + outcome.reason();
    }

    void abort(long id) {
        prepared.remove(id);
    }
}

package org.fdnet.corba;

import org.fdnet.corba.idl.ModuleOp;
import org.fdnet.corba.idl.NetworkCoordinator;
import org.fdnet.corba.idl.NetworkDescription;
import org.fdnet.corba.idl.Outcome;
import org.fdnet.corba.idl.Refused;
import org.fdnet.corba.idl.UnknownNode;
import org.fdnet.corba.idl.UnknownServant;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.MessageRefusedException;
import org.fdnet.runtime.NetworkEdit;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.WholeNetwork;
import org.omg.CORBA.SystemException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A host's view of the whole distributed network, for its Relations' Servants: every question and change goes to
 * the network's {@link NetworkCoordinator}.
 *
 * <pre>
 *   Paste.pasteRelation(edit) ─▶ describeNetwork() ─▶ edit applied to a copy here ─▶ applyEdit(after, basedOn)
 *        ◀── Outcome (executed on every host it touched, or refused: nothing changed anywhere)
 * </pre>
 *
 * An edit travels as the whole definition after it, with the version it was made on: the coordinator refuses it
 * when the network changed meanwhile (another Relation's paste), so two edits never silently overwrite each other.
 */
final class CoordinatorView implements WholeNetwork {
    private static final Logger LOG = LoggerFactory.getLogger(CoordinatorView.class);

    private final NetworkCoordinator coordinator;
    private final String hostName;

    /** @param hostName the host whose Relations see the network through this view */
    CoordinatorView(NetworkCoordinator coordinator, String hostName) {
        this.coordinator = coordinator;
        this.hostName = hostName;
    }

    @Override
    public Value message(String path, String message, Value argument) {
        try {
            return ValueCodec.decodeRuntime(coordinator.sendMessage(hostName, path, message, ValueCodec.encode(argument)));
        } catch (UnknownServant e) {
            throw new MessageRefusedException("no servant at " + path + " on any host of this network");
        } catch (Refused e) {
            throw new MessageRefusedException(e.reason);
        } catch (SystemException e) {
            throw new MessageRefusedException("the coordinator of this network does not answer (" + e + "): message "
                    + message + " to " + path + " not delivered");
        }
    }

    @Override
    public Snapshot snapshot() {
        return NetworkDescriptions.decode(describe());
    }

    private NetworkDescription describe() {
        try {
            return coordinator.describeNetwork();
        } catch (SystemException e) {
            throw new IllegalStateException("the coordinator of this network does not answer (" + e + ")", e);
        }
    }

    @Override
    public Value value(NodeRef data) {
        try {
            return RuntimeLocalNetwork.toRuntime(ValueCodec.decode(coordinator.read(IdlMapping.id(data))));
        } catch (UnknownNode | Refused e) {
            return null; // not running, or no value yet
        } catch (SystemException e) {
            LOG.debug("value of {} not available: {}", data, e.toString());
            return null;
        }
    }

    @Override
    public ChangeOutcome apply(String description, NetworkEdit edit) {
        NetworkDescription base;
        try {
            base = describe();
        } catch (IllegalStateException e) {
            return ChangeOutcome.failed(description, e.getMessage());
        }
        Snapshot now = NetworkDescriptions.decode(base);
        NetworkInfo after = now.definition();
        try {
            edit.applyTo(after);
        } catch (RuntimeException e) {
            LOG.info("change {} refused here, before it reached the coordinator: {}", description, e.toString());
            return ChangeOutcome.failed(description, e.getMessage() == null ? e.toString() : e.getMessage());
        }
        try {
            return outcome(description, coordinator.applyEdit(description, base.version,
                    NetworkDescriptions.encode(base.version, new Snapshot(after, now.loaded(), now.placedOn()))));
        } catch (SystemException e) {
            return ChangeOutcome.failed(description, "the coordinator of this network does not answer (" + e + ")");
        }
    }

    @Override
    public ChangeOutcome load(String module) {
        return module(ModuleOp.MO_LOAD, "load " + module, module);
    }

    @Override
    public ChangeOutcome unload(String module) {
        return module(ModuleOp.MO_UNLOAD, "unload " + module, module);
    }

    @Override
    public ChangeOutcome hold(String module) {
        return module(ModuleOp.MO_HOLD, "hold " + module, module);
    }

    @Override
    public ChangeOutcome resume(String module) {
        return module(ModuleOp.MO_RESUME, "resume " + module, module);
    }

    private ChangeOutcome module(ModuleOp op, String description, String module) {
        try {
            return outcome(description, coordinator.changeModule(op, module));
        } catch (SystemException e) {
            return ChangeOutcome.failed(description, "the coordinator of this network does not answer (" + e + ")");
        }
    }

    private static ChangeOutcome outcome(String description, Outcome o) {
        ChangeOutcome outcome = o.executed ? ChangeOutcome.executed(o.text) : ChangeOutcome.failed(description, o.text);
        LOG.info("change asked of the whole network: {}", outcome);
        return outcome;
    }
}

package org.fdnet.corba;

import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.ModuleOp;
import org.fdnet.corba.idl.NetworkCoordinator;
import org.fdnet.corba.idl.NetworkCoordinatorHelper;
import org.fdnet.corba.idl.NetworkCoordinatorPOA;
import org.fdnet.corba.idl.NetworkDescription;
import org.fdnet.corba.idl.NodeId;
import org.fdnet.corba.idl.Outcome;
import org.fdnet.corba.idl.Refused;
import org.fdnet.corba.idl.UnknownNode;
import org.fdnet.corba.idl.UnknownServant;
import org.fdnet.corba.idl.Value;
import java.util.ArrayList;
import java.util.List;
import java.util.function.Supplier;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.tls.Right;
import org.omg.CORBA.SystemException;

/**
 * The CORBA servant of {@code interface NetworkCoordinator}: what every host's Servants ask about the whole network
 * and how they reshape it, served by the process that runs the network over a {@link DistributedControl}.
 * {@link #publish} activates it on that process's ORB and tells every host of the deployment about it. The calling
 * host's certificate needs {@code read} to read a Data, {@code reshape} on every module an edit changes and on the
 * modules at both ends of every connection it makes or removes, {@code load}, {@code unload} or {@code reshape} (hold,
 * resume) on the module it changes, and {@code reshape} of every module to send a servant message ({@link Caller}).
 */
public final class CoordinatorServant extends NetworkCoordinatorPOA {
    private final DistributedControl control;

    CoordinatorServant(DistributedControl control) {
        this.control = control;
    }

    /** Serves {@code control} on {@code orb} and introduces it to every host (now and when hosts join or return). */
    public static NetworkCoordinator publish(OrbRuntime orb, DistributedControl control) {
        NetworkCoordinator ref = NetworkCoordinatorHelper.narrow(orb.activate(new CoordinatorServant(control)));
        control.deployment().introduce(ref);
        return ref;
    }

    @Override
    public NetworkDescription describeNetwork() {
        return control.description();
    }

    @Override
    public Value read(NodeId data) throws UnknownNode, Refused {
        Caller.require(Right.READ, IdlMapping.ref(data));
        String home = control.homeOf(IdlMapping.ref(data));
        Host host = home == null ? null : control.deployment().host(home);
        if (host == null) {
            throw new UnknownNode(data);
        }
        try {
            return host.read(data);
        } catch (SystemException e) {
            throw new Refused("host " + home + " of " + IdlMapping.ref(data) + " does not answer (" + e + ")");
        }
    }

    @Override
    public Outcome applyEdit(String description, long basedOn, NetworkDescription after) {
        NetworkInfo definition;
        try {
            definition = NetworkDescriptions.decode(after).definition();
        } catch (RuntimeException e) {
            return outcome(ChangeOutcome.failed(description, "the edited network is not valid: " + e.getMessage()
                    + "; nothing changed on any host"));
        }
        String refusal = Caller.refusalToEdit(NetworkDescriptions.decode(control.description()).definition(), definition);
        if (refusal != null) {
            return outcome(ChangeOutcome.failed(description, refusal + "; nothing changed on any host"));
        }
        return whenFree(description, () -> control.applyDefinition(description, basedOn, definition));
    }

    @Override
    public Outcome changeModule(ModuleOp op, String moduleName) {
        Right right = switch (op.value()) {
            case ModuleOp._MO_LOAD -> Right.LOAD;
            case ModuleOp._MO_UNLOAD -> Right.UNLOAD;
            default -> Right.RESHAPE;
        };
        String refusal = Caller.refusal(right, moduleName);
        if (refusal != null) {
            return outcome(ChangeOutcome.failed(right.word() + " " + moduleName, refusal));
        }
        return switch (op.value()) {
            case ModuleOp._MO_LOAD -> whenFree("load " + moduleName, () -> control.load(moduleName));
            case ModuleOp._MO_UNLOAD -> whenFree("unload " + moduleName, () -> control.unload(moduleName));
            case ModuleOp._MO_HOLD -> whenFree("hold " + moduleName, () -> control.hold(moduleName));
            default -> whenFree("resume " + moduleName, () -> control.resume(moduleName));
        };
    }

    @Override
    public Value sendMessage(String fromHost, String servantPath, String message, Value argument)
            throws UnknownServant, Refused {
        Caller.requireEveryModule(Right.RESHAPE);
        List<String> silent = new ArrayList<>();
        for (String name : control.deployment().plan().hosts()) {
            Host host = control.deployment().host(name);
            if (name.equals(fromHost) || host == null) {
                continue;
            }
            try {
                return host.answerMessage(servantPath, message, argument);
            } catch (UnknownServant e) {
                // not on this host: ask the next
            } catch (SystemException e) {
                silent.add(name + " (" + e + ")");
            }
        }
        if (!silent.isEmpty()) {
            throw new Refused("no host that answers has a servant at " + servantPath + "; these do not answer: "
                    + String.join(", ", silent));
        }
        throw new UnknownServant(servantPath);
    }

    /** A change a host's Relation asks: refused at once while another change runs (it may be what started it). */
    private Outcome whenFree(String description, Supplier<ChangeOutcome> change) {
        return outcome(control.deployment().ifNoChangeRuns(change).orElseGet(() -> ChangeOutcome.failed(description,
                "another change of this network is being made right now; nothing changed on any host (try again)")));
    }

    private static Outcome outcome(ChangeOutcome o) {
        return new Outcome(o.executed(), o.executed() ? o.description() : o.reason());
    }
}

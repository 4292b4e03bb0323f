package org.fdnet.corba.control;

import java.util.Optional;
import org.fdnet.control.NetworkUnreachableException;
import org.fdnet.corba.OrbRuntime;
import org.fdnet.corba.idl.RunningNetwork;
import org.fdnet.corba.idl.RunningNetworkHelper;
import org.omg.CORBA.ORBPackage.InvalidName;
import org.omg.CORBA.SystemException;
import org.omg.CosNaming.NameComponent;
import org.omg.CosNaming.NamingContextExt;
import org.omg.CosNaming.NamingContextExtHelper;
import org.omg.CosNaming.NamingContextPackage.NotFound;

/**
 * Running networks' control objects in the naming service: each is bound at the root context under the
 * network's name with kind {@value #KIND} (hosts are bound beside them with kind {@code fdnet-host}).
 */
public final class NetworkDirectory {
    public static final String KIND = "fdnet-network";

    private final NamingContextExt naming;
    private final String where;

    private NetworkDirectory(NamingContextExt naming, String where) {
        this.naming = naming;
        this.where = where;
    }

    /** The naming service {@code orb} was configured with. */
    public static NetworkDirectory connect(OrbRuntime orb) {
        String where = orb.settings().namingReference();
        if (where == null) {
            throw new IllegalStateException("no naming service configured (use --naming or --naming-port)");
        }
        try {
            return new NetworkDirectory(NamingContextExtHelper.narrow(
                    orb.orb().resolve_initial_references("NameService")), where);
        } catch (InvalidName | SystemException e) {
            throw new NetworkUnreachableException("naming service " + where + " is not reachable: " + e, e);
        }
    }

    public void register(String networkName, RunningNetwork network) {
        try {
            naming.rebind(path(networkName), network);
        } catch (org.omg.CORBA.UserException | SystemException e) {
            throw new NetworkUnreachableException("cannot register network '" + networkName + "' in " + where + ": "
                    + e, e);
        }
    }

    /** Removes the name when it still means {@code network} (a newer run of the same name keeps its own). */
    public void unregister(String networkName, RunningNetwork network) {
        try {
            if (find(networkName).filter(n -> n._is_equivalent(network)).isPresent()) {
                naming.unbind(path(networkName));
            }
        } catch (NotFound e) {
            // already gone
        } catch (org.omg.CORBA.UserException | SystemException e) {
            throw new NetworkUnreachableException("cannot unregister network '" + networkName + "' from " + where
                    + ": " + e, e);
        }
    }

    /** The control object registered under {@code networkName}, or empty when none is. */
    public Optional<RunningNetwork> find(String networkName) {
        try {
            return Optional.of(RunningNetworkHelper.unchecked_narrow(naming.resolve(path(networkName))));
        } catch (NotFound e) {
            return Optional.empty();
        } catch (org.omg.CORBA.UserException | SystemException e) {
            throw new NetworkUnreachableException("cannot look up network '" + networkName + "' in " + where + ": "
                    + e, e);
        }
    }

    public String where() {
        return where;
    }

    private static NameComponent[] path(String networkName) {
        return new NameComponent[] {new NameComponent(networkName, KIND)};
    }
}

package org.fdnet.corba;

import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.HostHelper;
import org.omg.CORBA.ORBPackage.InvalidName;
import org.omg.CORBA.SystemException;
import org.omg.CosNaming.Binding;
import org.omg.CosNaming.BindingIteratorHolder;
import org.omg.CosNaming.BindingListHolder;
import org.omg.CosNaming.NameComponent;
import org.omg.CosNaming.NamingContextExt;
import org.omg.CosNaming.NamingContextExtHelper;
import org.omg.CosNaming.NamingContextPackage.NotFound;

/**
 * The hosts of distributed FDNetworks as the naming service knows them: each host is bound at the
 * root context under its name with kind {@value #KIND}. A host that restarts rebinds its name, so
 * resolving again finds the new incarnation.
 */
public final class HostDirectory {
    public static final String KIND = "fdnet-host";

    private final NamingContextExt naming;
    private final String where;

    private HostDirectory(NamingContextExt naming, String where) {
        this.naming = naming;
        this.where = where;
    }

    /** The naming service the ORB was configured with ({@link OrbSettings#namingReference()}). */
    public static HostDirectory connect(OrbRuntime orb) {
        String where = orb.settings().namingReference();
        if (where == null) {
            throw new IllegalStateException("no naming service configured (use --naming or --naming-port)");
        }
        try {
            NamingContextExt ctx = NamingContextExtHelper.narrow(orb.orb().resolve_initial_references("NameService"));
            return new HostDirectory(ctx, where);
        } catch (InvalidName | SystemException e) {
            throw new HostUnreachableException("naming service " + where + " is not reachable: " + e, e);
        }
    }

    public void register(String hostName, Host host) {
        try {
            naming.rebind(path(hostName), host);
        } catch (org.omg.CORBA.UserException | SystemException e) {
            throw new HostUnreachableException("cannot register host '" + hostName + "' in " + where + ": " + e, e);
        }
    }

    public void unregister(String hostName) {
        try {
            naming.unbind(path(hostName));
        } catch (NotFound e) {
            // Already gone: a newer incarnation or a cleanup got there first.
        } catch (org.omg.CORBA.UserException | SystemException e) {
            throw new HostUnreachableException("cannot unregister host '" + hostName + "' from " + where + ": " + e, e);
        }
    }

    /** The host registered under {@code hostName}, or empty when no host has that name. */
    public Optional<Host> find(String hostName) {
        try {
            return Optional.of(HostHelper.narrow(naming.resolve(path(hostName))));
        } catch (NotFound e) {
            return Optional.empty();
        } catch (org.omg.CORBA.UserException | SystemException e) {
            throw new HostUnreachableException("cannot look up host '" + hostName + "' in " + where + ": " + e, e);
        }
    }

    /** The names of every registered host. */
    public List<String> hostNames() {
        BindingListHolder list = new BindingListHolder();
        BindingIteratorHolder rest = new BindingIteratorHolder();
        try {
            naming.list(10_000, list, rest);
        } catch (SystemException e) {
            throw new HostUnreachableException("cannot list hosts in " + where + ": " + e, e);
        }
        List<String> names = new ArrayList<>();
        for (Binding b : list.value) {
            NameComponent last = b.binding_name[b.binding_name.length - 1];
            if (KIND.equals(last.kind)) {
                names.add(last.id);
            }
        }
        if (rest.value != null) {
            rest.value.destroy();
        }
        return names;
    }

    public String where() {
        return where;
    }

    private static NameComponent[] path(String hostName) {
        return new NameComponent[] {new NameComponent(hostName, KIND)};
    }
}

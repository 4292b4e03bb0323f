package org.fdnet.corba;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeSet;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import org.fdnet.corba.idl.ModuleConnection;
import org.fdnet.corba.idl.NodeId;
import org.fdnet.corba.idl.NodeSpec;
import org.fdnet.corba.idl.ShareChange;
import org.fdnet.corba.idl.StandInSpec;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.NetworkEdit;

/**
 * A host's side of structural changes of a running distributed network ({@code prepareShareChange}, then
 * {@code commitChange} or {@code abortChange} of {@code fdnet.idl}): {@link #prepare} checks the change — every
 * class to create allowed by this host's {@link ClassPolicy}, then the edit as the engine checks a change (valid on
 * this host's definition, every new node constructed and initialised) — without changing the engine, and keeps it; {@link #take} and {@link #execute} make it as one change of the engine; {@link #abort}
 * forgets it.
 */
final class ShareChanges {
    private final String hostName;
    private final LocalNetwork network;
    private final ClassPolicy policy;
    private final Map<Long, ShareChange> prepared = new ConcurrentHashMap<>();

    ShareChanges(String hostName, LocalNetwork network, ClassPolicy policy) {
        this.hostName = hostName;
        this.network = network;
        this.policy = policy;
    }

    /** Every module {@code change} touches: where its nodes, stand-ins and connections are. */
    static Set<String> modules(ShareChange change) {
        Set<String> modules = new TreeSet<>();
        for (ModuleConnection c : change.disconnect) {
            modules.add(c.moduleName);
            modules.add(c.connection.data.moduleName);
            modules.add(c.connection.relation.moduleName);
        }
        for (ModuleConnection c : change.connect) {
            modules.add(c.moduleName);
            modules.add(c.connection.data.moduleName);
            modules.add(c.connection.relation.moduleName);
        }
        for (NodeId gone : change.destroy) {
            modules.add(gone.moduleName);
        }
        for (StandInSpec standIn : change.standIns) {
            modules.add(standIn.spec.id.moduleName);
        }
        for (NodeSpec made : change.create) {
            modules.add(made.id.moduleName);
        }
        return modules;
    }

    /** The reason this host cannot execute {@code change}, or {@code ""}; a possible change is kept. */
    String prepare(ShareChange change) {
        for (NodeSpec spec : change.create) {
            String refusal = policy.refusal(IdlMapping.node(spec, hostName));
            if (refusal != null) {
                return "host " + hostName + " refuses " + IdlMapping.ref(spec.id) + ": " + refusal;
            }
        }
        String problem = network.check("its part of the change", edit(change));
        if (problem != null) {
            return "host " + hostName + ": " + problem;
        }
        prepared.put(change.id, change);
        return "";
    }

    /** The prepared change {@code id}, no longer kept; {@code null} when none is. */
    ShareChange take(long id) {
        return prepared.remove(id);
    }

    /**
     * Executes a change taken from the prepared ones; returns {@code null} when it was executed, else the reason.
     *
     * @param beforeDestroy told each node about to be destroyed (its links close first)
     */
    String execute(ShareChange change, Consumer<NodeRef> beforeDestroy) {
        for (NodeId n : change.destroy) {
            beforeDestroy.accept(IdlMapping.ref(n));
        }
        for (StandInSpec s : change.standIns) {
            network.expectStandIn(IdlMapping.ref(s.spec.id));
        }
        try {
            network.reshape(describe(change), edit(change));
            return null;
        } catch (RuntimeException e) {
            return "host " + hostName + ": " + (e.getMessage() == null ? e.toString() : e.getMessage());
        }
    }

    void abort(long id) {
        prepared.remove(id);
    }

    static String describe(ShareChange c) {
        List<String> parts = new ArrayList<>();
        if (c.create.length > 0) {
            parts.add("create " + c.create.length);
        }
        if (c.destroy.length > 0) {
            parts.add("destroy " + c.destroy.length);
        }
        if (c.standIns.length > 0) {
            parts.add(c.standIns.length + " stand-ins");
        }
        if (c.connect.length + c.disconnect.length > 0) {
            parts.add("connect " + c.connect.length + ", disconnect " + c.disconnect.length);
        }
        return "share change " + c.id + " (" + String.join(", ", parts) + ")";
    }

    /** The change as one edit of this host's definition; tolerant of what is already gone. */
    private NetworkEdit edit(ShareChange c) {
        return n -> {
            for (ModuleConnection mc : c.disconnect) {
                ConnectionInfo conn = IdlMapping.connection(mc.connection);
                if (n.module(mc.moduleName) != null && n.module(mc.moduleName).connections().contains(conn)) {
                    n.deleteConnection(mc.moduleName, conn);
                }
            }
            for (NodeId id : c.destroy) {
                NodeRef ref = IdlMapping.ref(id);
                if (n.node(ref) != null) {
                    n.deleteNode(ref);
                }
            }
            for (StandInSpec s : c.standIns) {
                NodeRef ref = IdlMapping.ref(s.spec.id);
                ensureModule(n, ref.module());
                if (n.node(ref) == null) {
                    n.addNode(ref.module(), IdlMapping.node(s.spec, s.homeHost));
                }
            }
            for (NodeSpec spec : c.create) {
                NodeInfo node = IdlMapping.node(spec, hostName);
                ensureModule(n, spec.id.moduleName);
                n.addNode(spec.id.moduleName, node);
            }
            for (ModuleConnection mc : c.connect) {
                ensureModule(n, mc.moduleName);
                n.addConnection(mc.moduleName, IdlMapping.connection(mc.connection));
            }
        };
    }

    private static void ensureModule(NetworkInfo n, String module) {
        if (n.module(module) == null) {
            n.addModule(module, true);
        }
    }
}

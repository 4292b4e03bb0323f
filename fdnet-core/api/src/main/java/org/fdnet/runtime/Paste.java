package org.fdnet.runtime;

import java.util.List;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * The Paste servant: creates and destroys nodes, connects and disconnects them. Each call is one change
 * request of the controller, logged with the calling Relation as its source (on one host; across hosts each host
 * logs its part as its controller's); a refused one changes nothing and says why. Connections are declared by the module of their Relation end. A node goes to the host its
 * {@code host} names: on a network over several hosts, Paste creates and connects it there (when that host allows
 * its class), prepared and committed on every host the change touches — refused anywhere, it changes nothing.
 */
public final class Paste {
    private final ServantScope scope;

    Paste(ServantScope scope) {
        this.scope = scope;
    }

    public ChangeOutcome create(String module, NodeInfo node) {
        return scope.apply("create " + module + "/" + node.name(), NetworkEdits.addNode(module, node));
    }

    public ChangeOutcome destroy(NodeRef node) {
        return scope.apply("destroy " + node, NetworkEdits.deleteNode(node));
    }

    /** The Relation {@code relation} reads {@code data}. */
    public ChangeOutcome connectReader(NodeRef data, NodeRef relation) {
        return connect(ConnectionInfo.reader(data, relation));
    }

    /** The Relation {@code relation} writes {@code data}. */
    public ChangeOutcome connectWriter(NodeRef relation, NodeRef data) {
        return connect(ConnectionInfo.writer(relation, data));
    }

    private ChangeOutcome connect(ConnectionInfo c) {
        return scope.apply("connect " + c, NetworkEdits.addConnection(c.relation().module(), c));
    }

    /** Removes the connection of this kind between the two nodes, whichever module declares it. */
    public ChangeOutcome disconnect(ConnectionKind kind, NodeRef data, NodeRef relation) {
        return scope.apply("disconnect " + kind.label() + " " + data + " / " + relation, network -> {
            for (var linked : network.connectionsOf(data)) {
                ConnectionInfo c = linked.connection();
                if (c.kind() == kind && c.relation().equals(relation)) {
                    network.deleteConnection(linked.module(), c);
                    return;
                }
            }
            throw new EditRefusedException("there is no " + kind.label() + " between " + data + " and " + relation);
        });
    }

    /** Makes a declared but inactive ({@code exist = no}) connection live (the thesis's "activate"). */
    public ChangeOutcome activate(ConnectionKind kind, NodeRef data, NodeRef relation) {
        return scope.apply("activate " + kind.label() + " " + data + " / " + relation, network -> {
            for (var linked : network.connectionsOf(data)) {
                ConnectionInfo c = linked.connection();
                if (c.kind() == kind && c.relation().equals(relation)) {
                    if (c.exists()) {
                        throw new EditRefusedException(c + " is already active");
                    }
                    network.deleteConnection(linked.module(), c);
                    network.addConnection(linked.module(), new ConnectionInfo(c.kind(), c.name(), c.data(),
                            c.relation(), true, c.dataInline(), c.relationInline()));
                    return;
                }
            }
            throw new EditRefusedException("there is no " + kind.label() + " between " + data + " and " + relation);
        });
    }

    /**
     * Creates a Relation and its connections as one change (all or nothing): it reads {@code reads} and
     * writes {@code writes}. Datas to create first can be passed in {@code newDatas} (same module).
     */
    public ChangeOutcome pasteRelation(String module, NodeInfo relation, List<NodeInfo> newDatas, List<NodeRef> reads,
                                       List<NodeRef> writes) {
        if (relation.kind() != NodeKind.RELATION) {
            return ChangeOutcome.failed("paste " + relation.name(), relation.name() + " is not a Relation");
        }
        NodeRef self = new NodeRef(module, relation.name());
        NetworkEdit edit = network -> {
            if (network.module(module) == null && !module.equals(ModuleInfo.MAIN)) {
                network.addModule(module, false);
            }
            for (NodeInfo d : newDatas) {
                network.addNode(module, d);
            }
            network.addNode(module, relation);
            for (NodeRef r : reads) {
                network.addConnection(module, ConnectionInfo.reader(r, self));
            }
            for (NodeRef w : writes) {
                network.addConnection(module, ConnectionInfo.writer(self, w));
            }
        };
        return scope.apply("paste " + self, edit);
    }
}

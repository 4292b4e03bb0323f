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

    /**
     * Creates a node; a node of a loaded module starts at once.
     *
     * @param module the module it goes into
     * @param node   its definition: kind, name, class, host, parameters
     * @return executed, or failed with the reason (e.g. the name is taken, the class cannot start)
     */
    public ChangeOutcome create(String module, NodeInfo node) {
        return scope.apply("create " + module + "/" + node.name(), NetworkEdits.addNode(module, node));
    }

    /**
     * Destroys a node with every connection touching it.
     *
     * @param node the node's module and name
     * @return executed, or failed with the reason (e.g. there is no such node)
     */
    public ChangeOutcome destroy(NodeRef node) {
        return scope.apply("destroy " + node, NetworkEdits.deleteNode(node));
    }

    /**
     * The Relation {@code relation} reads {@code data}.
     *
     * @param data     the Data to read
     * @param relation the Relation that reads it; its module declares the connection
     * @return executed, or failed with the reason (e.g. an end does not exist)
     */
    public ChangeOutcome connectReader(NodeRef data, NodeRef relation) {
        return connect(ConnectionInfo.reader(data, relation));
    }

    /**
     * The Relation {@code relation} writes {@code data}.
     *
     * @param relation the Relation that writes; its module declares the connection
     * @param data     the Data it writes
     * @return executed, or failed with the reason (e.g. an end does not exist)
     */
    public ChangeOutcome connectWriter(NodeRef relation, NodeRef data) {
        return connect(ConnectionInfo.writer(relation, data));
    }

    private ChangeOutcome connect(ConnectionInfo c) {
        return scope.apply("connect " + c, NetworkEdits.addConnection(c.relation().module(), c));
    }

    /**
     * Removes the connection of this kind between the two nodes, whichever module declares it.
     *
     * @param kind     Reader or Writer
     * @param data     the connection's Data end
     * @param relation the connection's Relation end
     * @return executed, or failed when there is no such connection
     */
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

    /**
     * Makes a declared but inactive ({@code exist = no}) connection live (the thesis's "activate").
     *
     * @param kind     Reader or Writer
     * @param data     the connection's Data end
     * @param relation the connection's Relation end
     * @return executed, or failed when there is no such connection or it is already active
     */
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
     *
     * @param module   the module it goes into, made (not loaded at start) when missing
     * @param relation the Relation's definition
     * @param newDatas Datas to create in {@code module} first, may be empty
     * @param reads    the Datas it reads, in Reader order
     * @param writes   the Datas it writes, in Writer order
     * @return executed, or failed with the reason (then nothing of it was made)
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

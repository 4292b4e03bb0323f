package org.fdnet.runtime.engine;

import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Data;
import org.fdnet.runtime.DeclaredParameters;
import org.fdnet.runtime.NodeLifecycle;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.loading.NodeClassException;
import org.fdnet.runtime.loading.NodeClassResolver;

/**
 * Makes running nodes from definitions: resolves the class, constructs it, checks the parameters against the
 * class's declarations ({@link DeclaredParameters}), runs {@code init} with them, reads the engine's own ones
 * (period, onInput, triggers). Every failure is a {@link NodeFailure} whose message names the node.
 */
final class NodeFactory {
    private final NodeClassResolver resolver;
    private final Dataflow flow;

    NodeFactory(NodeClassResolver resolver, Dataflow flow) {
        this.resolver = resolver;
        this.flow = flow;
    }

    /** A prepared Data: constructed and initialised, with its first value; not yet part of the network. */
    record PreparedData(Data data, Value initial) {
    }

    PreparedData prepareData(NodeRef ref, NodeInfo info) throws NodeFailure {
        Data data = (Data) construct(ref, info);
        NodeParameters params = NodeParameters.of(ref, info);
        try {
            DeclaredParameters.of(data.getClass()).check(params);
            NodeLifecycle.init(data, params);
            Value initial = NodeLifecycle.initialValue(data, params).convertTo(data.type());
            return new PreparedData(data, initial);
        } catch (Exception e) {
            throw new NodeFailure(message(ref, info, e), e);
        }
    }

    Relation prepareRelation(NodeRef ref, NodeInfo info) throws NodeFailure {
        Relation relation = (Relation) construct(ref, info);
        NodeParameters params = NodeParameters.of(ref, info);
        try {
            DeclaredParameters.of(relation.getClass()).check(params);
            NodeLifecycle.init(relation, params);
            return relation;
        } catch (Exception e) {
            throw new NodeFailure(message(ref, info, e), e);
        }
    }

    DataNode dataNode(int id, NodeRef ref, NodeInfo info, PreparedData prepared, boolean standIn) {
        DataNode node = new DataNode(id, ref, info, prepared.data(), standIn, flow);
        NodeLifecycle.bind(prepared.data(), node);
        return node;
    }

    RelationNode relationNode(int id, NodeRef ref, NodeInfo info, Relation relation) {
        NodeParameters p = NodeParameters.of(ref, info);
        long period = Relation.PERIOD.read(p);
        String triggerNames = Relation.TRIGGERS.read(p);
        boolean onInput = Relation.ON_INPUT.readOr(p, period == 0 || triggerNames != null);
        java.util.Set<String> triggers = null;
        if (triggerNames != null) {
            triggers = new java.util.HashSet<>();
            for (String t : triggerNames.split(",")) {
                if (!t.isBlank()) {
                    triggers.add(t.strip());
                }
            }
        }
        return new RelationNode(id, ref, info, relation, period, onInput, triggers, flow);
    }

    private Object construct(NodeRef ref, NodeInfo info) throws NodeFailure {
        try {
            return resolver.instantiate(ref, info);
        } catch (NodeClassException e) {
            throw new NodeFailure(e.getMessage(), e);
        }
    }

    private static String message(NodeRef ref, NodeInfo info, Exception e) {
        String text = e.getMessage() == null ? e.toString() : e.getMessage();
        return text.startsWith(ref.toString()) || text.startsWith(ref.spelledOut()) ? text
                : ref + " (" + info.className() + "): " + text;
    }

    /** A node that cannot be made. */
    static final class NodeFailure extends Exception {
        private static final long serialVersionUID = 1L;

        NodeFailure(String message, Throwable cause) {
            super(message, cause);
        }
    }
}

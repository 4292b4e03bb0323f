package org.fdnet.corba;

import java.util.ArrayList;
import java.util.List;
import java.util.UUID;
import org.fdnet.event.RunIdentity;
import org.fdnet.corba.idl.ConnectionSpec;
import org.fdnet.corba.idl.NodeId;
import org.fdnet.corba.idl.NodeSpec;
import org.fdnet.corba.idl.Param;
import org.fdnet.corba.idl.RunDescription;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;

/** The network model ({@code org.fdnet.netinfo}) to the IDL structs of {@code fdnet.idl} and back. */
public final class IdlMapping {
    private IdlMapping() {
    }

    public static NodeId id(NodeRef ref) {
        return new NodeId(ref.module(), ref.node());
    }

    public static NodeRef ref(NodeId id) {
        return new NodeRef(id.moduleName, id.nodeName);
    }

    /** A run's identity as it crosses the IDL. */
    public static RunDescription description(RunIdentity run) {
        return new RunDescription(run.id().toString(), run.network(), run.definition(), run.sha256(),
                run.startedMicros(), run.hosts().toArray(String[]::new));
    }

    /** @throws IllegalArgumentException when the id is not a UUID */
    public static RunIdentity run(RunDescription d) {
        return new RunIdentity(UUID.fromString(d.id), d.network, d.definition, d.sha256, d.startedMicros,
                List.of(d.hosts));
    }

    /** The spec of {@code node} in {@code module}; the host is not sent: the receiving host is the place. */
    public static NodeSpec spec(String module, NodeInfo node) {
        Param[] params = new Param[node.parameters().size()];
        for (int i = 0; i < params.length; i++) {
            Parameter p = node.parameters().get(i);
            params[i] = new Param(p.name() == null ? "" : p.name(),
                    p.type() == null ? "" : p.type().attribute(), p.value());
        }
        return new NodeSpec(node.kind() == NodeKind.DATA
                ? org.fdnet.corba.idl.NodeKind.NK_DATA : org.fdnet.corba.idl.NodeKind.NK_RELATION,
                new NodeId(module, node.name()), node.path(), node.className(), params);
    }

    /** The node a spec describes, placed on {@code host}. */
    public static NodeInfo node(NodeSpec spec, String host) {
        List<Parameter> params = new ArrayList<>(spec.params.length);
        for (Param p : spec.params) {
            params.add(new Parameter(p.name.isEmpty() ? null : p.name,
                    p.type.isEmpty() ? null : ParameterType.fromAttribute(p.type), p.value));
        }
        NodeKind kind = spec.kind == org.fdnet.corba.idl.NodeKind.NK_DATA ? NodeKind.DATA : NodeKind.RELATION;
        return new NodeInfo(kind, spec.id.nodeName, host, spec.path, spec.className, params);
    }

    public static ConnectionSpec spec(ConnectionInfo c) {
        return new ConnectionSpec(c.kind() == ConnectionKind.READER
                ? org.fdnet.corba.idl.ConnectionKind.CK_READER : org.fdnet.corba.idl.ConnectionKind.CK_WRITER,
                id(c.data()), id(c.relation()));
    }

    public static ConnectionInfo connection(ConnectionSpec spec) {
        return spec.kind == org.fdnet.corba.idl.ConnectionKind.CK_READER
                ? ConnectionInfo.reader(ref(spec.data), ref(spec.relation))
                : ConnectionInfo.writer(ref(spec.relation), ref(spec.data));
    }
}

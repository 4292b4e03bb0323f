package org.fdnet.corba;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.fdnet.corba.idl.ConnectionEntry;
import org.fdnet.corba.idl.ModuleEntry;
import org.fdnet.corba.idl.NetworkDescription;
import org.fdnet.corba.idl.NodeEntry;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.WholeNetwork;

/** The whole network ({@link WholeNetwork.Snapshot}) to the IDL {@code NetworkDescription} and back. */
final class NetworkDescriptions {
    private NetworkDescriptions() {
    }

    static NetworkDescription encode(long version, WholeNetwork.Snapshot snapshot) {
        NetworkInfo def = snapshot.definition();
        List<ModuleEntry> modules = new ArrayList<>();
        List<NodeEntry> nodes = new ArrayList<>();
        List<ConnectionEntry> connections = new ArrayList<>();
        for (ModuleInfo m : def.modules()) {
            modules.add(new ModuleEntry(m.name(), m.loadAtStart(), snapshot.loaded().contains(m.name())));
            for (NodeInfo n : m.nodes()) {
                NodeRef ref = new NodeRef(m.name(), n.name());
                nodes.add(new NodeEntry(IdlMapping.spec(m.name(), n), n.host(),
                        snapshot.placedOn().getOrDefault(ref, "")));
            }
            for (ConnectionInfo c : m.connections()) {
                connections.add(new ConnectionEntry(m.name(), IdlMapping.spec(c), c.name() == null ? "" : c.name(),
                        c.exists(), c.dataInline(), c.relationInline()));
            }
        }
        return new NetworkDescription(version, def.name() == null ? "" : def.name(),
                modules.toArray(ModuleEntry[]::new), nodes.toArray(NodeEntry[]::new),
                connections.toArray(ConnectionEntry[]::new));
    }

    static WholeNetwork.Snapshot decode(NetworkDescription d) {
        NetworkInfo def = new NetworkInfo(d.networkName.isEmpty() ? null : d.networkName);
        Set<String> loaded = new LinkedHashSet<>();
        for (ModuleEntry m : d.modules) {
            if (!m.name.equals(ModuleInfo.MAIN)) {
                def.addModule(m.name, m.loadAtStart);
            }
            if (m.loaded) {
                loaded.add(m.name);
            }
        }
        Map<NodeRef, String> placedOn = new LinkedHashMap<>();
        for (NodeEntry n : d.nodes) {
            NodeRef ref = def.addNode(n.spec.id.moduleName, IdlMapping.node(n.spec, n.host));
            if (!n.placedOn.isEmpty()) {
                placedOn.put(ref, n.placedOn);
            }
        }
        for (ConnectionEntry c : d.connections) {
            ConnectionInfo plain = IdlMapping.connection(c.connection);
            ConnectionKind kind = plain.kind();
            def.addConnection(c.moduleName, new ConnectionInfo(kind, c.name.isEmpty() ? null : c.name, plain.data(),
                    plain.relation(), c.exists, c.dataInline, c.relationInline));
        }
        return new WholeNetwork.Snapshot(def, Set.copyOf(loaded), Map.copyOf(placedOn));
    }
}

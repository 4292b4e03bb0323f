package org.fdnet.runtime.engine;

import java.util.ArrayList;
import java.util.Collection;
import java.util.Collections;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Set;
import org.fdnet.event.NetworkCommand;
import org.fdnet.netinfo.ModuleTree;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeListener;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.DataValueObserver;
import org.fdnet.runtime.NetworkEdit;
import org.fdnet.runtime.NetworkEdits;
import org.fdnet.runtime.RelationState;
import org.fdnet.runtime.RemoteLink;
import org.fdnet.runtime.Value;

/**
 * The {@link Controller} of one {@link RuntimeNetwork}, on behalf of one event source: the controller
 * itself (id 0) or a Relation using its Servants. Module requests check their preconditions and become
 * change requests; queries read the running nodes.
 */
final class NetworkController implements Controller {
    private final RuntimeNetwork network;
    private final int source;

    NetworkController(RuntimeNetwork network, int source) {
        this.network = network;
        this.source = source;
    }

    @Override
    public ChangeOutcome apply(String description, NetworkEdit edit) {
        return network.change(description, source, edit, null, null, Set.of(), List.of());
    }

    @Override
    public ChangeOutcome setParameter(NodeRef node, String name, String value) {
        return apply("set " + node + " " + name + "=" + value, NetworkEdits.setParameter(node, name, value));
    }

    @Override
    public ChangeOutcome load(String module) {
        String what = "load module " + module;
        Set<String> loaded = network.loaded();
        String refused = network.readDefinition(d -> ModuleTree.whyNotLoadable(d, loaded, module));
        if (refused != null) {
            return failed(what, refused);
        }
        Set<String> added = network.readDefinition(d -> ModuleTree.loadedWith(d, module));
        Set<String> next = new LinkedHashSet<>(loaded);
        next.addAll(added);
        return network.change(what, source, null, next, null, Set.of(), commands(NetworkCommand.LOAD, added));
    }

    @Override
    public ChangeOutcome unload(String module) {
        String what = "unload module " + module;
        Set<String> loaded = network.loaded();
        if (module.equals(org.fdnet.netinfo.ModuleInfo.MAIN)) {
            return failed(what, "module 'main' holds the network's core and is always loaded");
        }
        if (!loaded.contains(module)) {
            return failed(what, "module '" + module + "' is not loaded");
        }
        Set<String> next = ModuleTree.afterUnload(loaded, module);
        List<String> removed = new ArrayList<>(loaded);
        removed.removeAll(next);
        Collections.reverse(removed);
        return network.change(what, source, null, next, null, Set.of(), commands(NetworkCommand.UNLOAD, removed));
    }

    /** One command per module, in the given order (a nested module's load or unload is logged as its own). */
    private static List<RuntimeNetwork.NetworkCommandDraft> commands(NetworkCommand command, Collection<String> modules) {
        return modules.stream().map(m -> new RuntimeNetwork.NetworkCommandDraft(command, m)).toList();
    }

    @Override
    public ChangeOutcome hold(String module) {
        String what = "hold module " + module;
        if (!network.loaded().contains(module)) {
            return failed(what, "module '" + module + "' is not loaded");
        }
        Set<String> held = new LinkedHashSet<>(network.held());
        if (!held.add(module)) {
            return failed(what, "module '" + module + "' is already on hold");
        }
        return network.change(what, source, null, null, held, Set.of(),
                List.of(new RuntimeNetwork.NetworkCommandDraft(NetworkCommand.HOLD, module)));
    }

    @Override
    public ChangeOutcome resume(String module) {
        String what = "resume module " + module;
        Set<String> held = new LinkedHashSet<>(network.held());
        if (!held.remove(module)) {
            return failed(what, "module '" + module + "' is not on hold");
        }
        return network.change(what, source, null, null, held, Set.of(),
                List.of(new RuntimeNetwork.NetworkCommandDraft(NetworkCommand.RESUME, module)));
    }

    @Override
    public ChangeOutcome restart(NodeRef relation) {
        String what = "restart " + relation;
        if (network.relationNode(relation) == null) {
            return failed(what, relation + " is not a Relation running here");
        }
        return network.change(what, source, null, null, null, Set.of(relation), List.of());
    }

    private static ChangeOutcome failed(String what, String reason) {
        return ChangeOutcome.failed(what, reason);
    }

    @Override
    public void setValue(NodeRef data, Value value) {
        network.write(data, value);
    }

    @Override
    public void setValue(NodeRef data, String text) {
        DataNode d = network.dataNode(data);
        if (d == null) {
            throw new IllegalArgumentException(data + " is not a Data running here");
        }
        Value v;
        try {
            v = Value.parse(d.type, text);
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException(data + " holds " + d.type.name().toLowerCase() + " values: " + e.getMessage(), e);
        }
        network.write(data, v);
    }

    @Override
    public Value value(NodeRef data) {
        DataNode d = network.dataNode(data);
        return d == null ? null : d.value;
    }

    @Override
    public AutoCloseable observe(NodeRef data, DataValueObserver observer) {
        NodeKind kind = network.readDefinition(d -> d.node(data) == null ? null : d.node(data).kind());
        if (kind != NodeKind.DATA) {
            throw new IllegalArgumentException(data + " is not a Data of this network");
        }
        return network.observe(data, observer);
    }

    @Override
    public RelationState relationState(NodeRef relation) {
        RelationNode r = network.relationNode(relation);
        return r == null ? null : r.state();
    }

    @Override
    public List<RelationState> relationStates() {
        return network.relationsInOrder().stream().map(RelationNode::state).toList();
    }

    @Override
    public int nodeId(NodeRef node) {
        return network.idIfKnown(node);
    }

    @Override
    public Set<String> loadedModules() {
        return network.loaded();
    }

    @Override
    public Set<String> heldModules() {
        return network.held();
    }

    @Override
    public List<RemoteLink> remoteLinks() {
        return network.remoteLinks();
    }

    @Override
    public NetworkInfo snapshot() {
        return network.definitionCopy();
    }

    @Override
    public void addChangeListener(ChangeListener listener) {
        network.addListener(listener);
    }

    @Override
    public void removeChangeListener(ChangeListener listener) {
        network.removeListener(listener);
    }
}

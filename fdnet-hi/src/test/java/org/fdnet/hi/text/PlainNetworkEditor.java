package org.fdnet.hi.text;

import java.nio.file.Path;
import java.util.List;
import java.util.function.Supplier;

import org.fdnet.hi.edit.NetworkEditor;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.MergePolicy;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;

/**
 * The unit-level seam of the frames' tests: a {@link NetworkEditor} applying each edit straight to a
 * {@link NetworkInfo} (no undo); a refused edit becomes {@link EditResult#refused} with NetworkInfo's message.
 */
public final class PlainNetworkEditor implements NetworkEditor {
    private final NetworkInfo network;
    private final Path file;

    public PlainNetworkEditor(NetworkInfo network) {
        this(network, null);
    }

    /** An editor of {@code network} read from {@code file} (node paths are relative to its folder). */
    public PlainNetworkEditor(NetworkInfo network, Path file) {
        this.network = network;
        this.file = file;
    }

    @Override
    public Path networkFile() {
        return file;
    }

    @Override
    public NetworkInfo network() {
        return network;
    }

    private static EditResult run(Runnable edit) {
        try {
            edit.run();
            return EditResult.ok();
        } catch (EditRefusedException e) {
            return EditResult.refused(e.getMessage());
        }
    }

    private static EditResult node(Supplier<NodeRef> edit) {
        try {
            return EditResult.ok(edit.get());
        } catch (EditRefusedException e) {
            return EditResult.refused(e.getMessage());
        }
    }

    @Override
    public EditResult renameNetwork(String newName) {
        return run(() -> network.setName(newName));
    }

    @Override
    public EditResult addModule(String module, boolean loadAtStart) {
        return run(() -> network.addModule(module, loadAtStart));
    }

    @Override
    public EditResult deleteModule(String module) {
        return run(() -> network.deleteModule(module));
    }

    @Override
    public EditResult renameModule(String oldName, String newName) {
        return run(() -> network.renameModule(oldName, newName));
    }

    @Override
    public EditResult setLoadAtStart(String module, boolean loadAtStart) {
        return run(() -> network.setLoadAtStart(module, loadAtStart));
    }

    @Override
    public EditResult addNode(String module, NodeInfo node) {
        return node(() -> network.addNode(module, node));
    }

    @Override
    public EditResult updateNode(NodeRef ref, NodeInfo updated) {
        return run(() -> network.updateNode(ref, updated));
    }

    @Override
    public EditResult setParameters(NodeRef ref, List<Parameter> parameters) {
        return run(() -> network.setParameters(ref, parameters));
    }

    @Override
    public EditResult deleteNode(NodeRef ref) {
        return run(() -> network.deleteNode(ref));
    }

    @Override
    public EditResult renameNode(NodeRef ref, String newName) {
        return node(() -> network.renameNode(ref, newName));
    }

    @Override
    public EditResult replaceNode(NodeRef replaced, NodeRef replacement) {
        return node(() -> network.replaceNode(replaced, replacement));
    }

    @Override
    public EditResult mergeNodes(NodeRef first, NodeRef second, MergePolicy policy) {
        return node(() -> network.mergeNodes(first, second, policy));
    }

    @Override
    public EditResult addConnection(String module, ConnectionInfo connection) {
        return run(() -> network.addConnection(module, connection));
    }

    @Override
    public EditResult deleteConnection(String module, ConnectionInfo connection) {
        return run(() -> network.deleteConnection(module, connection));
    }
}

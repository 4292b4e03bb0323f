package org.fdnet.hi.app;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.fdnet.hi.edit.UndoableNetworkEditor;
import org.fdnet.hi.graph.GraphScene;
import org.fdnet.layout.ModuleLayout;
import org.fdnet.layout.NetworkLayout;
import org.fdnet.layout.NodeLayout;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.xml.LayoutRepository;
import org.fdnet.netinfo.xml.NetworkDocument;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;

/**
 * One network open in the editor: its file (none until first saved), the editor over its model, the
 * scene over its layout, and what saving must keep of the file (DOCTYPE, header comments). Saving writes
 * the .fdn and the .fdg beside it; the .fdg holds only nodes and modules the network still has.
 */
public final class OpenNetwork {
    private Path file;
    private final UndoableNetworkEditor editor;
    private final GraphScene scene;
    private final String doctype;
    private final List<String> comments;
    private final String layoutWarning;

    private OpenNetwork(Path file, NetworkInfo network, NetworkLayout layout, String doctype, List<String> comments,
                        String layoutWarning) {
        this.file = file;
        this.editor = new UndoableNetworkEditor(network, layout);
        this.editor.setNetworkFile(file);
        this.scene = new GraphScene(editor);
        this.doctype = doctype;
        this.comments = comments;
        this.layoutWarning = layoutWarning;
    }

    public static OpenNetwork empty() {
        return new OpenNetwork(null, new NetworkInfo("untitled"), new NetworkLayout(), null, List.of(), null);
    }

    /** A running network's snapshot, not yet saved anywhere; laid out afresh. */
    public static OpenNetwork running(NetworkInfo snapshot) {
        return new OpenNetwork(null, snapshot, new NetworkLayout(), null, List.of(), null);
    }

    /**
     * Reads {@code file} and its .fdg. A network with problems throws (the window shows them, read-only);
     * a .fdg with problems is set aside with a warning and the network is laid out afresh.
     */
    public static OpenNetwork load(Path file) throws NetworkFileException {
        NetworkDocument doc = NetworkRepository.read(file);
        Path side = LayoutRepository.sideFileOf(file);
        NetworkLayout layout = new NetworkLayout();
        String warning = null;
        if (Files.isRegularFile(side)) {
            try {
                layout = LayoutRepository.load(side);
            } catch (NetworkFileException e) {
                warning = side.getFileName() + " has problems (" + e.problems().get(0) + "); laid out afresh";
            }
        }
        return new OpenNetwork(file, doc.network(), layout, doc.doctypeSystemId(), doc.leadingComments(), warning);
    }

    public Path file() {
        return file;
    }

    public UndoableNetworkEditor editor() {
        return editor;
    }

    public GraphScene scene() {
        return scene;
    }

    /** Set when the .fdg could not be used; {@code null} otherwise. */
    public String layoutWarning() {
        return layoutWarning;
    }

    /** Edits or view changes not yet saved. */
    public boolean unsaved() {
        return editor.dirty() || scene.layoutChanged();
    }

    public void saveAs(Path target) throws IOException {
        NetworkRepository.save(editor.network(), target, doctype, comments);
        LayoutRepository.save(savedLayout(), LayoutRepository.sideFileOf(target));
        file = target;
        editor.setNetworkFile(target);
        editor.markSaved();
        scene.markLayoutSaved();
    }

    /** The layout without entries for nodes and modules that are gone (undo keeps those in memory). */
    NetworkLayout savedLayout() {
        NetworkInfo network = editor.network();
        NetworkLayout all = editor.layout();
        NetworkLayout kept = new NetworkLayout();
        kept.setNetwork(network.name());
        for (ModuleInfo m : network.modules()) {
            ModuleLayout from = all.module(m.name());
            if (from == null) {
                continue;
            }
            ModuleLayout to = kept.moduleOrNew(m.name());
            to.setColour(from.colour());
            to.setVisible(from.visible());
            for (var e : from.nodes().entrySet()) {
                NodeLayout at = e.getValue();
                if (m.hasNode(e.getKey())) {
                    to.put(e.getKey(), at);
                }
            }
        }
        return kept;
    }
}

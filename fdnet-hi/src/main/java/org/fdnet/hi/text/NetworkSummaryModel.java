package org.fdnet.hi.text;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import org.fdnet.hi.edit.NetworkEditor;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.hi.speedy.SpeedyDesign;
import org.fdnet.hi.speedy.Updatable;
import org.fdnet.netinfo.ModuleCounts;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkChangeListener;
import org.fdnet.netinfo.NetworkInfo;

/**
 * The logic of the Network frame: the network in numbers (thesis §IX "FDNetworks in numbers") — one row per
 * module with its Datas, Relations, Readers and Writers ({@link NetworkInfo#counts}), and the total — and the
 * module form that adds, edits (rename, load at start) and deletes modules.
 *
 * <pre>
 *   network (root) ─▶ rows ─┐
 *   selected module (root) ─┴▶ module form (name, load at start, New or Edit)
 * </pre>
 */
public final class NetworkSummaryModel {
    /** One module in numbers. */
    public record ModuleRow(String name, boolean loadAtStart, ModuleCounts counts) { }

    private final NetworkEditor editor;
    private final SpeedyDesign speedy;
    private final NetworkChangeListener listener;
    private final Updatable network = Updatable.marker();
    private final Updatable rows = this::computeRows;
    private final Updatable typed = Updatable.marker();
    private final Updatable form = this::computeForm;

    private final List<ModuleRow> moduleRows = new ArrayList<>();
    private ModuleCounts total = new ModuleCounts(0, 0, 0, 0);
    private String typedName = "";
    private boolean typedLoadAtStart = true;
    private ModuleRow existing;

    public NetworkSummaryModel(NetworkEditor editor, SpeedyDesign speedy) {
        this.editor = Objects.requireNonNull(editor, "editor");
        this.speedy = speedy;
        speedy.register("network:network", network);
        speedy.register("network:rows", rows, network);
        speedy.register("network:typed", typed);
        speedy.register("network:form", form, rows, typed);
        listener = change -> speedy.changed(network);
        editor.network().addListener(listener);
        computeRows();
    }

    public void detach() {
        editor.network().removeListener(listener);
    }

    public Updatable rows() {
        return rows;
    }

    public Updatable form() {
        return form;
    }

    public String networkName() {
        String n = editor.network().name();
        return n == null ? "(unnamed)" : n;
    }

    public List<ModuleRow> moduleRows() {
        return List.copyOf(moduleRows);
    }

    public ModuleCounts total() {
        return total;
    }

    /** Types the module name in the module form; the name of an existing module turns New into Edit. */
    public void typeModuleName(String text) {
        typedName = text.strip();
        speedy.changed(typed);
    }

    public void chooseLoadAtStart(boolean load) {
        typedLoadAtStart = load;
        speedy.changed(typed);
    }

    public String typedModuleName() {
        return typedName;
    }

    /** The module the typed name names, or null. */
    public ModuleRow existingModule() {
        return existing;
    }

    /** "Edit" when the typed name is an existing module (its load flag is then set), else "New". */
    public String saveLabel() {
        return existing != null ? "Edit" : "New";
    }

    /** Adds the typed module, or sets an existing one's load-at-start flag. */
    public EditResult save() {
        if (typedName.isEmpty()) {
            return EditResult.refused("type the module's name");
        }
        if (existing != null) {
            return existing.loadAtStart() == typedLoadAtStart
                    ? EditResult.refused("module '" + typedName + "' already has load at start = " + typedLoadAtStart)
                    : editor.setLoadAtStart(typedName, typedLoadAtStart);
        }
        return editor.addModule(typedName, typedLoadAtStart);
    }

    public EditResult rename(String oldName, String newName) {
        return editor.renameModule(oldName, newName == null ? "" : newName.strip());
    }

    public EditResult delete(String moduleName) {
        return editor.deleteModule(moduleName);
    }

    private void computeRows() {
        moduleRows.clear();
        NetworkInfo net = editor.network();
        for (ModuleInfo m : net.modules()) {
            moduleRows.add(new ModuleRow(m.name(), m.loadAtStart(), net.counts(m.name())));
        }
        total = net.totalCounts();
    }

    private void computeForm() {
        existing = moduleRows.stream().filter(r -> r.name().equals(typedName)).findFirst().orElse(null);
    }
}

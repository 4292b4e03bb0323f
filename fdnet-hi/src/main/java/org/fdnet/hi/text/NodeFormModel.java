package org.fdnet.hi.text;

import java.util.ArrayList;
import java.util.List;
import java.util.Objects;

import org.fdnet.hi.edit.NetworkEditor;
import org.fdnet.hi.edit.NetworkEditor.EditResult;
import org.fdnet.hi.speedy.SpeedyDesign;
import org.fdnet.hi.speedy.Updatable;
import org.fdnet.netinfo.NetworkChangeListener;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.netinfo.ParameterType;
import org.fdnet.runtime.ParameterSpec;

/**
 * The logic of the Advanced Module frame's node tab (thesis Chapter 5 §IX): the node being typed, and what
 * follows from it. Typing the name of a node that exists in the module loads its kind, host, path, class and
 * parameters, and Save becomes Update; a name that exists nowhere keeps what the user typed.
 *
 * <pre>
 *   network (root) ─┐
 *   name (root) ────┴▶ existing ─▶ details ─▶ actions (Save/Update label, Delete enabled, why not)
 * </pre>
 *
 * The class typed is looked up as a run would look it up ({@link NodeClasses}): the form lists the parameters it
 * declares, with their descriptions, offers each as a new row, and offers the classes the network's paths hold.
 *
 * Each box is a SpeedyDesign component; a view registers its widgets with {@link #speedy()} as children of
 * {@link #details()} or {@link #actions()}. Edits go through the {@link NetworkEditor} only.
 */
public final class NodeFormModel {
    private final NetworkEditor editor;
    private String module;
    private final SpeedyDesign speedy;
    private final NetworkChangeListener listener;

    private final Updatable network = Updatable.marker();
    private final Updatable name = Updatable.marker();
    private final Updatable existing = this::findExisting;
    private final Updatable details = this::loadDetails;
    private final Updatable actions = Updatable.marker();

    private String typedName = "";
    private NodeRef loaded;
    private NodeRef detailsOf;
    private NodeInfo lastLoaded;
    private NodeKind kind = NodeKind.DATA;
    private String host = "localhost";
    private String path = "";
    private String className = "";
    private final List<Parameter> parameters = new ArrayList<>();
    private final NodeClasses classes;

    public NodeFormModel(NetworkEditor editor, String module, SpeedyDesign speedy) {
        this.editor = Objects.requireNonNull(editor, "editor");
        this.module = Objects.requireNonNull(module, "module");
        this.speedy = speedy;
        this.classes = new NodeClasses(editor::networkFile);
        speedy.register("node:network", network);
        speedy.register("node:name", name);
        speedy.register("node:existing", existing, network, name);
        speedy.register("node:details", details, existing);
        speedy.register("node:actions", actions, existing, details);
        listener = change -> {
            this.module = ModuleRenames.follow(this.module, change);
            speedy.changed(network);
        };
        editor.network().addListener(listener);
    }

    /** Stops following the network (the frame closed). */
    public void detach() {
        editor.network().removeListener(listener);
        classes.close();
    }

    public SpeedyDesign speedy() {
        return speedy;
    }

    /** The component the detail widgets (kind, host, path, class, parameter table) depend on. */
    public Updatable details() {
        return details;
    }

    /** The component the Save/Update and Delete buttons depend on. */
    public Updatable actions() {
        return actions;
    }

    public String module() {
        return module;
    }

    // ------------------------------------------------------------ what the user types

    public void typeName(String text) {
        typedName = text.strip();
        speedy.changed(name);
    }

    public void chooseKind(NodeKind k) {
        kind = Objects.requireNonNull(k);
        speedy.changed(details);
    }

    public void typeHost(String text) {
        host = text.strip();
        speedy.changed(details);
    }

    public void typePath(String text) {
        path = text.strip();
        speedy.changed(details);
    }

    public void typeClass(String text) {
        className = text.strip();
        speedy.changed(details);
    }

    /** Takes a class the network's paths offer: its name and its path. */
    public void chooseClass(NodeClasses.Choice choice) {
        path = choice.path();
        className = choice.className();
        speedy.changed(details);
    }

    /** Reads the paths' classes again (a jar was rebuilt). */
    public void rescanClasses() {
        classes.forget();
        speedy.changed(details);
    }

    /**
     * Adds a parameter to the draft; {@code type} null means untyped, a blank {@code paramName} means positional.
     *
     * @return null, or why the parameter was refused (e.g. a "long" that is not a whole number)
     */
    public String addParameter(String paramName, ParameterType type, String value) {
        return putParameter(parameters.size(), false, paramName, type, value);
    }

    /** Replaces the parameter at {@code index}; returns null or why it was refused. */
    public String editParameter(int index, String paramName, ParameterType type, String value) {
        if (index < 0 || index >= parameters.size()) {
            return "choose the parameter to edit in the table first";
        }
        return putParameter(index, true, paramName, type, value);
    }

    public void deleteParameter(int index) {
        if (index >= 0 && index < parameters.size()) {
            parameters.remove(index);
            speedy.changed(details);
        }
    }

    private String putParameter(int index, boolean replace, String paramName, ParameterType type, String value) {
        Parameter p;
        try {
            String n = paramName == null || paramName.isBlank() ? null : paramName.strip();
            p = new Parameter(n, type, value == null ? "" : value);
        } catch (IllegalArgumentException e) {
            return "parameter " + (index + 1) + ": " + e.getMessage();
        }
        if (replace) {
            parameters.set(index, p);
        } else {
            parameters.add(p);
        }
        speedy.changed(details);
        return null;
    }

    // ------------------------------------------------------------ the state

    public String name() {
        return typedName;
    }

    /** The node the typed name names in this module, or null for a new node. */
    public NodeRef loaded() {
        return loaded;
    }

    public NodeKind kind() {
        return kind;
    }

    public String host() {
        return host;
    }

    public String path() {
        return path;
    }

    public String className() {
        return className;
    }

    public List<Parameter> parameters() {
        return List.copyOf(parameters);
    }

    /** The classes of the chosen kind that the network's paths and the typed path offer. */
    public List<NodeClasses.Choice> classChoices() {
        return classes.choices(editor.network(), path, kind);
    }

    /** Why a path of the last {@link #classChoices} could not be scanned for classes, or null. */
    public String classScanProblem() {
        return classes.scanProblem();
    }

    /** The parameters the typed class declares, its own first (empty when it cannot be found: see {@link #declaredProblem}). */
    public List<ParameterSpec<?>> declaredParameters() {
        NodeClasses.Declared d = classes.declared(kind, path, className);
        return d.parameters() == null ? List.of() : d.parameters().all();
    }

    /** Why the typed class's parameters cannot be listed, or null. */
    public String declaredProblem() {
        return classes.declared(kind, path, className).problem();
    }

    /** What the parameter fields are filled with when a declared parameter is chosen (type null: untyped). */
    public record Offer(String name, ParameterType type, String value) {
    }

    /**
     * A declared parameter as the fields offer it for adding: its name, its type (text untyped), and its default
     * value when it has one.
     *
     * @return the offer, or null when the typed class declares no parameter of that name
     */
    public Offer offered(String declaredName) {
        for (ParameterSpec<?> spec : declaredParameters()) {
            if (spec.name().equals(declaredName)) {
                ParameterType type = spec.fileType() == ParameterType.STRING ? null : spec.fileType();
                return new Offer(spec.name(), type, spec.hasDefaultValue() ? spec.defaultText() : "");
            }
        }
        return null;
    }

    /** "Update" when the typed name is an existing node of the module, else "Save". */
    public String saveLabel() {
        return loaded != null ? "Update" : "Save";
    }

    public boolean canDelete() {
        return loaded != null;
    }

    /** Why Save/Update cannot run now, or null when it can. */
    public String whyNotSave() {
        if (editor.network().module(module) == null) {
            return "module '" + module + "' no longer exists";
        }
        if (typedName.isEmpty()) {
            return "type the node's name";
        }
        if (typedName.contains("/")) {
            return "a node name cannot contain '/'";
        }
        if (className.isEmpty()) {
            return "type the node's class";
        }
        if (host.isEmpty()) {
            return "type the node's host";
        }
        return null;
    }

    // ------------------------------------------------------------ actions

    /** Adds the typed node, or updates the loaded one (Save / Update). */
    public EditResult save() {
        String why = whyNotSave();
        if (why != null) {
            return EditResult.refused(why);
        }
        NodeInfo node = new NodeInfo(kind, typedName, host, path, className, parameters);
        if (loaded != null) {
            return editor.updateNode(loaded, node);
        }
        return editor.addNode(module, node);
    }

    /** Deletes the loaded node and, through the editor, every connection that names it. */
    public EditResult delete() {
        if (loaded == null) {
            return EditResult.refused("no node named '" + typedName + "' in module '" + module + "' to delete");
        }
        return editor.deleteNode(loaded);
    }

    // ------------------------------------------------------------ updates (SpeedyDesign)

    private void findExisting() {
        var m = editor.network().module(module);
        loaded = m != null && !typedName.isEmpty() && m.hasNode(typedName) ? new NodeRef(module, typedName) : null;
    }

    /** Loads the existing node's details once when its name is typed, and again when the network changed it. */
    private void loadDetails() {
        if (loaded == null) {
            detailsOf = null;
            return;
        }
        NodeInfo node = editor.network().node(loaded);
        if (loaded.equals(detailsOf) && !changedElsewhere(node)) {
            return;
        }
        detailsOf = loaded;
        kind = node.kind();
        host = node.host();
        path = node.path();
        className = node.className();
        parameters.clear();
        parameters.addAll(node.parameters());
        lastLoaded = node;
    }

    private boolean changedElsewhere(NodeInfo node) {
        return !node.equals(lastLoaded);
    }
}

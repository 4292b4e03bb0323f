package org.fdnet.layout;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Objects;

/** A module's colour and visibility in the editor, and the layout of its nodes by name. */
public final class ModuleLayout {
    private final String name;
    private String colour;
    private boolean visible = true;
    private final LinkedHashMap<String, NodeLayout> nodes = new LinkedHashMap<>();

    /**
     * A visible module without colour and without node layouts.
     *
     * @param name the module's full name, not null
     */
    public ModuleLayout(String name) {
        this.name = Objects.requireNonNull(name, "name");
    }

    /**
     * The module this layout is for.
     *
     * @return the module's full name
     */
    public String name() {
        return name;
    }

    /**
     * The module's colour in the editor.
     *
     * @return {@code #RRGGBB}, or null for the editor's default
     */
    public String colour() {
        return colour;
    }

    /**
     * Sets the module's colour.
     *
     * @param newColour {@code #RRGGBB}, or null for the editor's default
     * @throws IllegalArgumentException when the colour is not of the form {@code #RRGGBB}
     */
    public void setColour(String newColour) {
        colour = Colour.check(newColour);
    }

    /**
     * Whether the editor shows the module's nodes.
     *
     * @return true unless hidden
     */
    public boolean visible() {
        return visible;
    }

    /**
     * Shows or hides the module's nodes in the editor.
     *
     * @param newVisible true to show them
     */
    public void setVisible(boolean newVisible) {
        visible = newVisible;
    }

    /**
     * The node layouts by node name.
     *
     * @return an unmodifiable live view, in the order they were put
     */
    public Map<String, NodeLayout> nodes() {
        return Collections.unmodifiableMap(nodes);
    }

    /**
     * One node's layout.
     *
     * @param nodeName the node's name in this module
     * @return its layout, or null when it has none (the editor then places it)
     */
    public NodeLayout node(String nodeName) {
        return nodes.get(nodeName);
    }

    /**
     * Sets one node's layout, replacing any it had.
     *
     * @param nodeName the node's name in this module, not null
     * @param layout   its layout, not null
     */
    public void put(String nodeName, NodeLayout layout) {
        nodes.put(Objects.requireNonNull(nodeName), Objects.requireNonNull(layout));
    }

    /**
     * Forgets one node's layout; nothing happens when it has none.
     *
     * @param nodeName the node's name in this module
     */
    public void remove(String nodeName) {
        nodes.remove(nodeName);
    }

    @Override
    public boolean equals(Object o) {
        return o instanceof ModuleLayout m && name.equals(m.name) && Objects.equals(colour, m.colour)
                && visible == m.visible && nodes.equals(m.nodes);
    }

    @Override
    public int hashCode() {
        return Objects.hash(name, colour, visible, nodes);
    }
}

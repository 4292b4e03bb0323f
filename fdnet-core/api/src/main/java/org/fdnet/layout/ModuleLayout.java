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

    public ModuleLayout(String name) {
        this.name = Objects.requireNonNull(name, "name");
    }

    public String name() {
        return name;
    }

    public String colour() {
        return colour;
    }

    public void setColour(String newColour) {
        colour = Colour.check(newColour);
    }

    public boolean visible() {
        return visible;
    }

    public void setVisible(boolean newVisible) {
        visible = newVisible;
    }

    public Map<String, NodeLayout> nodes() {
        return Collections.unmodifiableMap(nodes);
    }

    public NodeLayout node(String nodeName) {
        return nodes.get(nodeName);
    }

    public void put(String nodeName, NodeLayout layout) {
        nodes.put(Objects.requireNonNull(nodeName), Objects.requireNonNull(layout));
    }

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

package org.fdnet.runtime;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.function.BooleanSupplier;

/**
 * One servant of the servant tree (thesis Appendix 2: "root servants, parent servants, child servants"): a name,
 * one parent (none for the root), children by name, and the {@link MessageServant} that answers its messages
 * ({@code null} for a servant that only groups others). Its path is its names from the root, {@code /arm/planner}.
 * Thread-safe; a servant answers one message at a time.
 */
public final class ServantNode {
    private final String name;
    private final ServantNode parent;
    private final MessageServant servant;
    private final BooleanSupplier ownerRuns;
    private final Map<String, ServantNode> children = new LinkedHashMap<>();

    ServantNode(String name, ServantNode parent, MessageServant servant) {
        this(name, parent, servant, () -> true);
    }

    /** @param ownerRuns whether the Relation that offered it still runs (a servant does not outlive it) */
    ServantNode(String name, ServantNode parent, MessageServant servant, BooleanSupplier ownerRuns) {
        this.name = name;
        this.parent = parent;
        this.servant = servant;
        this.ownerRuns = ownerRuns;
    }

    /** Whether the Relation that offered this servant still runs (always, for one no Relation offered). */
    boolean ownerRuns() {
        return ownerRuns.getAsBoolean();
    }

    /**
     * This servant's own name, the last part of its path.
     *
     * @return the name, empty for the root
     */
    public String name() {
        return name;
    }

    /**
     * The parent servant, or {@code null} for the root.
     *
     * @return the parent, or null
     */
    public ServantNode getParent() {
        return parent;
    }

    /**
     * The servant every other descends from.
     *
     * @return the root of this servant's tree
     */
    public ServantNode getRootServant() {
        ServantNode n = this;
        while (n.parent != null) {
            n = n.parent;
        }
        return n;
    }

    /**
     * {@code /} for the root, else the names from the root: {@code /arm/planner}.
     *
     * @return the absolute path
     */
    public String path() {
        return parent == null ? "/" : (parent.parent == null ? "" : parent.path()) + "/" + name;
    }

    /**
     * Whether this servant answers messages (a grouping servant does not).
     *
     * @return true when a {@link MessageServant} stands behind it
     */
    public boolean answers() {
        return servant != null;
    }

    /**
     * The child called {@code childName}.
     *
     * @param childName the child's own name
     * @return the child, or null when there is none of that name
     */
    public synchronized ServantNode child(String childName) {
        return children.get(childName);
    }

    /**
     * The children, in the order they joined.
     *
     * @return a new list
     */
    public synchronized List<ServantNode> children() {
        return new ArrayList<>(children.values());
    }

    /** This servant's answer to {@code message}; one message at a time. */
    Value answer(String message, Value argument) {
        if (servant == null) {
            throw new MessageRefusedException("servant " + path() + " only groups other servants: it answers no message");
        }
        synchronized (servant) {
            return servant.answer(message, argument);
        }
    }

    synchronized ServantNode childOrAdd(String childName, MessageServant answering) {
        return children.computeIfAbsent(childName, n -> new ServantNode(n, this, answering));
    }

    /** Adds {@code child} unless a servant of that name is there whose Relation still runs. */
    synchronized boolean adopt(ServantNode child) {
        ServantNode there = children.get(child.name);
        if (there != null && there.ownerRuns()) {
            return false;
        }
        children.put(child.name, child);
        return true;
    }

    synchronized void release(ServantNode child) {
        children.remove(child.name, child);
    }

    @Override
    public String toString() {
        return "servant " + path();
    }
}

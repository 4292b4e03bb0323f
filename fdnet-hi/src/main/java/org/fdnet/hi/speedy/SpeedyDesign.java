package org.fdnet.hi.speedy;

import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.HashSet;
import java.util.IdentityHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;

/**
 * The thesis's component handler (Chapter 5 §X): components register with the components they depend on
 * (their parents); when one changes, every component that depends on it, directly or not, updates itself
 * <em>exactly once</em>, parents before children — never n to n! times as when each component asks its
 * descendants itself.
 *
 * <pre>
 *   user edits A ──▶ changed(A) ──▶ descendants of A, ordered by level ──▶ B.update(), C.update(), D.update()
 *                                   (level = longest chain of parents above a component)
 * </pre>
 *
 * A dependency that would close a loop is refused when it is declared, naming the loop. A component that
 * reports a change while it is being updated (a Swing field firing its listener when its text is set) is
 * already covered by the cascade in progress, so that report is ignored; a change reported meanwhile by a
 * component outside the cascade runs after it. Use from one thread (Swing's event thread).
 */
public final class SpeedyDesign {
    private final Map<Updatable, Node> nodes = new IdentityHashMap<>();
    private final Deque<Updatable> pending = new ArrayDeque<>();
    private Set<Updatable> cascade;

    private static final class Node {
        final Updatable component;
        final String name;
        final int order;
        final List<Node> parents = new ArrayList<>();
        final List<Node> children = new ArrayList<>();
        int level;

        Node(Updatable component, String name, int order) {
            this.component = component;
            this.name = name;
            this.order = order;
        }
    }

    /**
     * Registers {@code component} under {@code name} (for messages) with the components it depends on, which
     * must be registered already.
     *
     * @throws IllegalArgumentException when it is registered already or a parent is not
     */
    public void register(String name, Updatable component, Updatable... parents) {
        if (nodes.containsKey(component)) {
            throw new IllegalArgumentException("component '" + name + "' is registered already as '"
                    + nodes.get(component).name + "'");
        }
        for (Updatable p : parents) {
            if (!nodes.containsKey(p)) {
                throw new IllegalArgumentException("component '" + name + "' depends on a component that is not"
                        + " registered; register the parents first");
            }
        }
        Node node = new Node(component, name, nodes.size());
        nodes.put(component, node);
        for (Updatable p : parents) {
            link(nodes.get(p), node);
        }
        relevel();
    }

    /**
     * Declares that {@code child} depends on {@code parent} as well (both registered).
     *
     * @throws IllegalArgumentException when the dependency would close a loop, naming it
     */
    public void dependsOn(Updatable child, Updatable parent) {
        Node c = known(child);
        Node p = known(parent);
        List<Node> loop = path(c, p);
        if (loop != null) {
            StringBuilder names = new StringBuilder();
            for (Node n : loop) {
                names.append(n.name).append(" → ");
            }
            names.append(c.name);
            throw new IllegalArgumentException("'" + c.name + "' cannot depend on '" + p.name
                    + "': that closes the loop " + names);
        }
        link(p, c);
        relevel();
    }

    /**
     * Tells the handler that {@code source} changed (it updated its own state): every component depending on it
     * updates once, in level order.
     */
    public void changed(Updatable source) {
        Node node = known(source);
        if (cascade != null) {
            if (!cascade.contains(source)) {
                pending.add(source);
            }
            return;
        }
        run(node);
        while (!pending.isEmpty()) {
            run(known(pending.poll()));
        }
    }

    /** Updates every registered component once, in level order (to fill a frame when it opens). */
    public void updateAll() {
        List<Node> all = new ArrayList<>(nodes.values());
        all.sort(SpeedyDesign::byLevel);
        cascade = new HashSet<>(nodes.keySet());
        try {
            for (Node n : all) {
                n.component.update();
            }
        } finally {
            cascade = null;
        }
    }

    private void run(Node source) {
        Set<Node> reached = new LinkedHashSet<>();
        Deque<Node> todo = new ArrayDeque<>(source.children);
        while (!todo.isEmpty()) {
            Node n = todo.poll();
            if (reached.add(n)) {
                todo.addAll(n.children);
            }
        }
        List<Node> order = new ArrayList<>(reached);
        order.sort(SpeedyDesign::byLevel);
        cascade = new HashSet<>();
        cascade.add(source.component);
        for (Node n : order) {
            cascade.add(n.component);
        }
        try {
            for (Node n : order) {
                n.component.update();
            }
        } finally {
            cascade = null;
        }
    }

    private static int byLevel(Node a, Node b) {
        return a.level != b.level ? Integer.compare(a.level, b.level) : Integer.compare(a.order, b.order);
    }

    private Node known(Updatable component) {
        Node n = nodes.get(component);
        if (n == null) {
            throw new IllegalArgumentException("component is not registered with this SpeedyDesign handler");
        }
        return n;
    }

    private static void link(Node parent, Node child) {
        if (!child.parents.contains(parent)) {
            child.parents.add(parent);
            parent.children.add(child);
        }
    }

    /** A path of children from {@code from} to {@code to}, or null. */
    private static List<Node> path(Node from, Node to) {
        if (from == to) {
            return List.of(from);
        }
        for (Node c : from.children) {
            List<Node> rest = path(c, to);
            if (rest != null) {
                List<Node> p = new ArrayList<>();
                p.add(from);
                p.addAll(rest);
                return p;
            }
        }
        return null;
    }

    /** Level = the longest chain of parents above a component (roots are 0); parents always sort first. */
    private void relevel() {
        List<Node> all = new ArrayList<>(nodes.values());
        all.sort((a, b) -> Integer.compare(a.order, b.order));
        boolean moved = true;
        for (Node n : all) {
            n.level = 0;
        }
        while (moved) {
            moved = false;
            for (Node n : all) {
                for (Node p : n.parents) {
                    if (n.level < p.level + 1) {
                        n.level = p.level + 1;
                        moved = true;
                    }
                }
            }
        }
    }
}

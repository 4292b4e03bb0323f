package org.fdnet.control;

import java.util.ArrayList;
import java.util.Comparator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.runtime.NetworkEdit;

/**
 * What changed between two definitions of one network — modules, nodes (their class, path, host, parameters)
 * and connections added, removed or changed — as a list to show ({@link #entries()}) and as one edit
 * ({@link #asEdit()}) that makes the same changes to a <em>third</em> definition: the running one, which may
 * have changed meanwhile (its Relations reshape it through their Servants).
 *
 * <p>The edit checks, change by change, that what the difference starts from is still there: a node it
 * changes still has the old class or parameter value, a node it adds is not there yet, a connection it
 * removes is still declared. When one no longer fits, the edit throws {@link EditRefusedException} naming the
 * conflict; the controller then changes nothing. Changes the running network made that the difference does
 * not touch are kept. The network's name and the order of declarations are not part of the difference.
 */
public final class NetworkDiff {
    /** Whether an entry adds, removes or changes something; its symbol leads the entry's text. */
    public enum Change {
        ADDED("+"), REMOVED("-"), CHANGED("~");

        private final String symbol;

        Change(String symbol) {
            this.symbol = symbol;
        }

        public String symbol() {
            return symbol;
        }
    }

    /**
     * One line of the difference: {@code + node Walk/gain}, {@code ~ Balance/keep parameter margin 0.02 → 0.03},
     * {@code - connection Legs/ik → Legs/targets}.
     *
     * @param change  added, removed or changed
     * @param subject what: {@code module M}, {@code node M/N}, {@code connection A → B}, or {@code M/N} for a change of a node
     * @param detail  for a changed node, what changed in it; else empty
     */
    public record Entry(Change change, String subject, String detail) {
        public Entry {
            Objects.requireNonNull(change, "change");
            Objects.requireNonNull(subject, "subject");
            Objects.requireNonNull(detail, "detail");
        }

        /** The line to display. */
        public String text() {
            return change.symbol() + " " + subject + (detail.isEmpty() ? "" : " " + detail);
        }

        @Override
        public String toString() {
            return text();
        }
    }

    /** One change of the difference with the step that makes it; steps run in {@link Step#order}. */
    private record Item(Entry entry, Step step, Apply apply) {
    }

    /** The order steps run in: what goes first (so a removed name can be reused), then what comes. */
    private enum Step {
        REMOVE_CONNECTION, REMOVE_NODE, REMOVE_MODULE, ADD_MODULE, CHANGE_MODULE, ADD_NODE, CHANGE_NODE,
        ADD_CONNECTION;

        int order() {
            return ordinal();
        }
    }

    private interface Apply {
        void to(NetworkInfo target);
    }

    private final List<Entry> entries;
    private final List<Apply> steps;

    private NetworkDiff(List<Item> items, List<Apply> steps) {
        this.entries = items.stream().map(Item::entry).toList();
        this.steps = List.copyOf(steps);
    }

    /** The difference that turns {@code base} into {@code edited}. */
    public static NetworkDiff between(NetworkInfo base, NetworkInfo edited) {
        return new Builder(base, edited).build();
    }

    /** Every change, modules first, then nodes, then connections; empty when the two definitions mean the same. */
    public List<Entry> entries() {
        return entries;
    }

    public boolean isEmpty() {
        return entries.isEmpty();
    }

    /**
     * The same changes as an edit of another definition, all or nothing (the controller applies it to a copy).
     * Throws {@link EditRefusedException} naming the first change that no longer fits the definition it is
     * applied to.
     */
    public NetworkEdit asEdit() {
        return target -> {
            for (Apply step : steps) {
                step.to(target);
            }
        };
    }

    @Override
    public String toString() {
        return entries.isEmpty() ? "no changes" : String.join("\n", entries.stream().map(Entry::text).toList());
    }

    // ------------------------------------------------------------------------------------------ building

    private static final class Builder {
        private final NetworkInfo base;
        private final NetworkInfo edited;
        private final List<Item> items = new ArrayList<>();

        Builder(NetworkInfo base, NetworkInfo edited) {
            this.base = Objects.requireNonNull(base, "base");
            this.edited = Objects.requireNonNull(edited, "edited");
        }

        NetworkDiff build() {
            modules();
            nodes();
            connections();
            List<Item> ordered = new ArrayList<>(items);
            ordered.sort(Comparator.comparingInt(i -> i.step().order()));
            return new NetworkDiff(items, ordered.stream().map(Item::apply).toList());
        }

        private void add(Change change, String subject, String detail, Step step, Apply apply) {
            items.add(new Item(new Entry(change, subject, detail), step, apply));
        }

        private void modules() {
            for (ModuleInfo m : edited.modules()) {
                ModuleInfo before = base.module(m.name());
                String name = m.name();
                boolean loadAtStart = m.loadAtStart();
                if (before == null) {
                    add(Change.ADDED, "module " + name, "", Step.ADD_MODULE, target -> {
                        if (target.module(name) != null) {
                            throw new EditRefusedException("cannot add module '" + name
                                    + "': the running network already has a module of that name");
                        }
                        target.addModule(name, loadAtStart);
                    });
                } else if (before.loadAtStart() != loadAtStart) {
                    add(Change.CHANGED, "module " + name, loadAtStart ? "loaded at start" : "not loaded at start",
                            Step.CHANGE_MODULE, target -> target.setLoadAtStart(name, loadAtStart));
                }
            }
            for (ModuleInfo m : base.modules()) {
                String name = m.name();
                if (edited.module(name) == null) {
                    add(Change.REMOVED, "module " + name, "", Step.REMOVE_MODULE, target -> {
                        if (target.module(name) == null) {
                            throw new EditRefusedException("cannot remove module '" + name
                                    + "': the running network no longer has it");
                        }
                        target.deleteModule(name);
                    });
                }
            }
        }

        private void nodes() {
            for (ModuleInfo m : edited.modules()) {
                boolean newModule = base.module(m.name()) == null;
                for (NodeInfo node : m.nodes()) {
                    NodeRef ref = new NodeRef(m.name(), node.name());
                    NodeInfo before = newModule ? null : base.node(ref);
                    if (before == null) {
                        add(Change.ADDED, "node " + ref, "", Step.ADD_NODE, target -> {
                            if (target.node(ref) != null) {
                                throw new EditRefusedException("cannot add node " + ref
                                        + ": the running network already has a node of that name");
                            }
                            target.addNode(ref.module(), node);
                        });
                    } else if (!before.equals(node)) {
                        nodeChanges(ref, before, node);
                    }
                }
            }
            for (ModuleInfo m : base.modules()) {
                if (edited.module(m.name()) == null) {
                    continue; // the module goes with its nodes
                }
                for (NodeInfo node : m.nodes()) {
                    NodeRef ref = new NodeRef(m.name(), node.name());
                    if (edited.node(ref) == null) {
                        add(Change.REMOVED, "node " + ref, "", Step.REMOVE_NODE, target -> {
                            if (target.node(ref) == null) {
                                throw new EditRefusedException("cannot remove node " + ref
                                        + ": the running network no longer has it");
                            }
                            target.deleteNode(ref);
                        });
                    }
                }
            }
        }

        /** One entry per changed attribute and per changed named parameter; positional parameters change as a list. */
        private void nodeChanges(NodeRef ref, NodeInfo before, NodeInfo after) {
            attribute(ref, "kind", before.kind().label(), after.kind().label(),
                    (n, v) -> new NodeInfo(after.kind(), n.name(), n.host(), n.path(), n.className(), n.parameters()),
                    n -> n.kind().label());
            attribute(ref, "class", before.className(), after.className(),
                    (n, v) -> new NodeInfo(n.kind(), n.name(), n.host(), n.path(), v, n.parameters()), NodeInfo::className);
            attribute(ref, "path", before.path(), after.path(),
                    (n, v) -> new NodeInfo(n.kind(), n.name(), n.host(), v, n.className(), n.parameters()), NodeInfo::path);
            attribute(ref, "host", before.host(), after.host(), (n, v) -> n.withHost(v), NodeInfo::host);
            if (before.parameters().equals(after.parameters())) {
                return;
            }
            if (allNamed(before.parameters()) && allNamed(after.parameters())) {
                namedParameterChanges(ref, before.parameters(), after.parameters());
            } else {
                List<Parameter> from = before.parameters();
                List<Parameter> to = after.parameters();
                add(Change.CHANGED, ref.toString(), "parameters " + from + " → " + to, Step.CHANGE_NODE, target -> {
                    NodeInfo current = requireNode(target, ref);
                    if (!current.parameters().equals(from)) {
                        throw new EditRefusedException(ref + ": its parameters are " + current.parameters()
                                + " in the running network, not " + from + " as when the edit began");
                    }
                    target.setParameters(ref, to);
                });
            }
        }

        private interface NodeAttribute {
            NodeInfo with(NodeInfo node, String value);
        }

        private void attribute(NodeRef ref, String what, String from, String to, NodeAttribute setter,
                               java.util.function.Function<NodeInfo, String> getter) {
            if (from.equals(to)) {
                return;
            }
            add(Change.CHANGED, ref.toString(), what + " " + shown(from) + " → " + shown(to), Step.CHANGE_NODE, target -> {
                NodeInfo current = requireNode(target, ref);
                String now = getter.apply(current);
                if (!now.equals(from)) {
                    throw new EditRefusedException(ref + ": its " + what + " is " + shown(now)
                            + " in the running network, not " + shown(from) + " as when the edit began");
                }
                target.updateNode(ref, setter.with(current, to));
            });
        }

        private void namedParameterChanges(NodeRef ref, List<Parameter> from, List<Parameter> to) {
            Map<String, Parameter> before = byName(from);
            Map<String, Parameter> after = byName(to);
            for (Parameter p : to) {
                Parameter old = before.get(p.name());
                if (old == null) {
                    add(Change.CHANGED, ref.toString(), "parameter " + p.name() + " added = " + p.value(),
                            Step.CHANGE_NODE, target -> {
                                NodeInfo current = requireNode(target, ref);
                                Parameter now = byName(current.parameters()).get(p.name());
                                if (now != null) {
                                    throw new EditRefusedException(ref + ": the running network already gives it"
                                            + " parameter " + p.name() + " = " + now.value());
                                }
                                List<Parameter> updated = new ArrayList<>(current.parameters());
                                updated.add(p);
                                target.setParameters(ref, updated);
                            });
                } else if (!old.equals(p)) {
                    String detail = old.type() == p.type()
                            ? "parameter " + p.name() + " " + old.value() + " → " + p.value()
                            : "parameter " + p.name() + " " + old + " → " + p;
                    add(Change.CHANGED, ref.toString(), detail, Step.CHANGE_NODE,
                            target -> replaceParameter(target, ref, old, p));
                }
            }
            for (Parameter p : from) {
                if (!after.containsKey(p.name())) {
                    add(Change.CHANGED, ref.toString(), "parameter " + p.name() + " removed", Step.CHANGE_NODE,
                            target -> replaceParameter(target, ref, p, null));
                }
            }
        }

        private static void replaceParameter(NetworkInfo target, NodeRef ref, Parameter old, Parameter replacement) {
            NodeInfo current = requireNode(target, ref);
            Parameter now = byName(current.parameters()).get(old.name());
            if (!old.equals(now)) {
                throw new EditRefusedException(ref + ": parameter " + old.name() + " is "
                        + (now == null ? "absent" : now.value()) + " in the running network, not " + old.value()
                        + " as when the edit began");
            }
            List<Parameter> updated = new ArrayList<>();
            for (Parameter p : current.parameters()) {
                if (!old.name().equals(p.name())) {
                    updated.add(p);
                } else if (replacement != null) {
                    updated.add(replacement);
                }
            }
            target.setParameters(ref, updated);
        }

        private void connections() {
            for (ModuleInfo m : edited.modules()) {
                ModuleInfo before = base.module(m.name());
                for (ConnectionInfo c : m.connections()) {
                    if (before == null || !declares(before, c)) {
                        String module = m.name();
                        add(Change.ADDED, "connection " + flow(c), "", Step.ADD_CONNECTION, target -> {
                            if (target.module(module) != null && declares(target.module(module), c)) {
                                throw new EditRefusedException("cannot add connection " + flow(c)
                                        + ": the running network already has it");
                            }
                            target.addConnection(module, c);
                        });
                    }
                }
            }
            for (ModuleInfo m : base.modules()) {
                ModuleInfo after = edited.module(m.name());
                if (after == null) {
                    continue; // the module goes with the connections it declares
                }
                for (ConnectionInfo c : m.connections()) {
                    if (!declares(after, c) && stillHasEnds(c)) {
                        String module = m.name();
                        add(Change.REMOVED, "connection " + flow(c), "", Step.REMOVE_CONNECTION,
                                target -> removeConnection(target, module, c));
                    }
                }
            }
        }

        /**
         * A connection whose end node or module goes is removed with it, so it is not an entry of its own, except
         * when the end stays (then the connection was removed by itself).
         */
        private boolean stillHasEnds(ConnectionInfo c) {
            return edited.node(c.data()) != null && edited.node(c.relation()) != null;
        }

        private static void removeConnection(NetworkInfo target, String module, ConnectionInfo c) {
            ModuleInfo m = target.module(module);
            ConnectionInfo declared = null;
            if (m != null) {
                for (ConnectionInfo candidate : m.connections()) {
                    if (candidate.sameLink(c)) {
                        declared = candidate;
                        break;
                    }
                }
            }
            if (declared == null) {
                throw new EditRefusedException("cannot remove connection " + flow(c)
                        + ": the running network no longer has it");
            }
            target.deleteConnection(module, declared);
        }

        private static boolean declares(ModuleInfo module, ConnectionInfo c) {
            for (ConnectionInfo candidate : module.connections()) {
                if (candidate.sameDeclaration(c)) {
                    return true;
                }
            }
            return false;
        }

        private static NodeInfo requireNode(NetworkInfo target, NodeRef ref) {
            NodeInfo node = target.node(ref);
            if (node == null) {
                throw new EditRefusedException("cannot change node " + ref + ": the running network no longer has it");
            }
            return node;
        }

        private static boolean allNamed(List<Parameter> parameters) {
            java.util.Set<String> names = new java.util.HashSet<>();
            for (Parameter p : parameters) {
                if (p.name() == null || !names.add(p.name())) {
                    return false;
                }
            }
            return true;
        }

        private static Map<String, Parameter> byName(List<Parameter> parameters) {
            Map<String, Parameter> map = new LinkedHashMap<>();
            for (Parameter p : parameters) {
                if (p.name() != null) {
                    map.putIfAbsent(p.name(), p);
                }
            }
            return map;
        }

        private static String shown(String text) {
            return text.isEmpty() ? "(none)" : text;
        }
    }

    /** {@code Legs/ik → Legs/targets}: the direction values flow. */
    static String flow(ConnectionInfo c) {
        return c.kind() == ConnectionKind.READER
                ? c.data() + " → " + c.relation()
                : c.relation() + " → " + c.data();
    }
}

package org.fdnet.runtime.engine;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.Collection;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.RelationStatus;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The last step of a structural change (structure lock held): every local Relation gets the wiring the
 * plan declares — a slot per declared connection, the running Data behind it or {@code null} — and every
 * Data the list of Relations its new values trigger. A Relation whose wiring changed is asked to fire once,
 * so it sees its new inputs; its status (RUNNING, WAITING with what is missing, HELD) is reported when it
 * changes.
 */
final class Rewiring {
    private static final Logger LOG = LoggerFactory.getLogger(Rewiring.class);

    private Rewiring() {
    }

    /** Gives every local Relation its wiring and every Data its readers; reports status changes. */
    static void apply(Collection<RelationNode> relations, Map<NodeRef, DataNode> datas, Set<LiveLink> links,
                      Set<String> held, StructurePlan plan, Set<RelationNode> toRequest, EventPublisher events) {
        Map<NodeRef, List<RelationNode>> readersOf = new HashMap<>();
        for (RelationNode r : relations) {
            List<LiveLink> declared = plan.declared.getOrDefault(r.ref, List.of());
            List<NodeRef> inRefs = new ArrayList<>();
            List<DataNode> ins = new ArrayList<>();
            List<NodeRef> outRefs = new ArrayList<>();
            List<DataNode> outs = new ArrayList<>();
            List<NodeRef> missing = new ArrayList<>();
            for (LiveLink l : declared) {
                DataNode d = links.contains(l) ? datas.get(l.data()) : null;
                if (d == null) {
                    missing.add(l.data());
                }
                if (l.kind() == ConnectionKind.READER) {
                    inRefs.add(l.data());
                    ins.add(d);
                    if (d != null && r.triggeredBy(l.data())) {
                        readersOf.computeIfAbsent(l.data(), k -> new ArrayList<>()).add(r);
                    }
                } else {
                    outRefs.add(l.data());
                    outs.add(d);
                }
            }
            Wiring next = new Wiring(inRefs.toArray(NodeRef[]::new), ins.toArray(DataNode[]::new),
                    outRefs.toArray(NodeRef[]::new), outs.toArray(DataNode[]::new));
            Wiring current = r.wiring;
            if (!sameWiring(current, next)) {
                r.wiring = next;
                toRequest.add(r);
            }
            r.missing = List.copyOf(missing);
            boolean isHeld = held.contains(r.ref.module());
            boolean resumed = r.held && !isHeld;
            r.held = isHeld;
            if (resumed && r.missedWhileHeld) {
                r.missedWhileHeld = false;
                toRequest.add(r);
            }
            updateStatus(r, events);
        }
        for (DataNode d : datas.values()) {
            List<RelationNode> readers = readersOf.getOrDefault(d.ref, List.of());
            d.readers = readers.toArray(RelationNode[]::new);
        }
    }

    private static boolean sameWiring(Wiring a, Wiring b) {
        return Arrays.equals(a.inputRefs(), b.inputRefs()) && Arrays.equals(a.outputRefs(), b.outputRefs())
                && identical(a.inputs(), b.inputs()) && identical(a.outputs(), b.outputs());
    }

    private static boolean identical(DataNode[] a, DataNode[] b) {
        if (a.length != b.length) {
            return false;
        }
        for (int i = 0; i < a.length; i++) {
            if (a[i] != b[i]) {
                return false;
            }
        }
        return true;
    }

    private static void updateStatus(RelationNode r, EventPublisher events) {
        if (r.status == RelationStatus.FAILED || !r.alive) {
            return;
        }
        RelationStatus next = r.held ? RelationStatus.HELD
                : r.missing.isEmpty() ? RelationStatus.RUNNING : RelationStatus.WAITING;
        String before = r.reportedState;
        r.status = next;
        String now = r.state().text();
        if (!now.equals(before)) {
            r.reportedState = now;
            if (next == RelationStatus.WAITING) {
                LOG.info("{} {}", r.ref, now);
            }
            events.relationValue(r.id, now);
        }
    }

}

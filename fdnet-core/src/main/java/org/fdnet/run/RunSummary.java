package org.fdnet.run;

import java.io.PrintWriter;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import org.fdnet.event.ValueType;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.RelationState;
import org.fdnet.runtime.RelationStatus;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.engine.RuntimeNetwork;

/**
 * The summary a run prints at its end, of this process's engine: firings, values and events, events by kind,
 * every Data (values written here, last value; a Data that runs on another host says so) and every Relation with
 * its state and the causes of failures.
 */
final class RunSummary {
    private final NetworkInfo definition;
    private final RuntimeNetwork network;
    private final EventCounter counter;

    RunSummary(NetworkInfo definition, RuntimeNetwork network, EventCounter counter) {
        this.definition = definition;
        this.network = network;
        this.counter = counter;
    }

    void print(PrintWriter out, long startedNanos) {
        Controller c = network.controller();
        double seconds = (System.nanoTime() - startedNanos) / 1e9;
        out.printf(Locale.ROOT, "%nsummary of %s after %.1f s: %,d firings, %,d values, %,d events%n",
                definition.name() == null ? "(unnamed)" : definition.name(), seconds, network.firings(),
                network.writes(), counter.total());
        out.println("events by kind:");
        for (Map.Entry<String, Long> e : counter.byKind().entrySet()) {
            out.printf(Locale.ROOT, "  %-20s %,d%n", e.getKey(), e.getValue());
        }
        out.println("Datas (values written, last value):");
        for (ModuleInfo m : definition.modules()) {
            for (NodeInfo n : m.nodes()) {
                if (n.kind() != NodeKind.DATA) {
                    continue;
                }
                NodeRef ref = new NodeRef(m.name(), n.name());
                int id = c.nodeId(ref);
                Value v = c.value(ref);
                out.printf(Locale.ROOT, "  %-45s %,8d  %s%n", ref, id < 0 ? 0 : counter.valuesOf(id),
                        v == null ? "(not running here)" : shortText(v));
            }
        }
        out.println("Relations (firings, state):");
        List<RelationState> failed = new ArrayList<>();
        for (RelationState s : c.relationStates()) {
            out.printf(Locale.ROOT, "  %-45s %,8d  %s%n", s.relation(), s.firings(), s.status());
            if (s.status() == RelationStatus.FAILED) {
                failed.add(s);
            }
        }
        if (failed.isEmpty()) {
            out.println("failed Relations: none");
        } else {
            out.println("failed Relations:");
            failed.forEach(s -> out.println("  " + s.relation() + ": " + s.cause()));
        }
        out.flush();
    }

    private static String shortText(Value v) {
        String text = v.text();
        if (v.type() == ValueType.DOUBLE || v.type() == ValueType.DOUBLES) {
            StringBuilder b = new StringBuilder(v.length() > 1 || v.type() == ValueType.DOUBLES ? "[" : "");
            for (int i = 0; i < v.length(); i++) {
                b.append(i == 0 ? "" : ", ").append(String.format(Locale.ROOT, "%.4f", v.element(i)));
            }
            text = b.append(v.type() == ValueType.DOUBLES ? "]" : "").toString();
        }
        return text.length() > 80 ? text.substring(0, 77) + "..." : text;
    }
}

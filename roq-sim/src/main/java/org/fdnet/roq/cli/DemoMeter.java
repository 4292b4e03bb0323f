package org.fdnet.roq.cli;

import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.atomic.LongAdder;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.roq.sim.LoopStatistics;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.view.DemoFigures;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.engine.RuntimeNetwork;

/**
 * Measures a demo run from what the network itself says, without depending on its node classes:
 * <pre>
 *   network events ──▶ DemoMeter (EventSink) ──▶ the logger client (when recording)
 *                        │ counts every event; the stability margin: every value the Data named "margin"
 *                        │ takes after its initial one (Balance's), or without one the last "margin X m" reported
 *   network Datas  ──▶ probes / fragile found / fragile avoided, read by name when a module has them
 *   simulator      ──▶ sim time, distance, broken cells, loop statistics
 *                        └──▶ {@link DemoFigures}
 * </pre>
 */
final class DemoMeter implements EventSink {
    /** Data names read, in any module, when present (a Probing module's counters). */
    static final String PROBES = "probes";
    static final String FRAGILE_FOUND = "fragile found";
    static final String FRAGILE_AVOIDED = "fragile avoided";
    /** The stability margin's Data (Balance's), m; its values are taken in preference to KeepBalance's report. */
    static final String MARGIN_DATA = "margin";
    private static final Pattern MARGIN = Pattern.compile("margin (-?\\d+(?:\\.\\d+)?) m.*");

    private final EventSink next;
    private final LongAdder events = new LongAdder();
    private volatile double margin = Double.NaN;
    private volatile double smallest = Double.NaN;
    /** The event source id of the Data named "margin", once the network has named it; -1 before. */
    private volatile int marginSource = -1;
    private volatile boolean marginInitialSeen;
    private final Map<String, NodeRef> counters = new HashMap<>();

    DemoMeter(EventSink next) {
        this.next = next;
    }

    /** Finds the counters' Datas by name in {@code network}'s definition. */
    void lookUpCounters(RuntimeNetwork network) {
        network.readDefinition(def -> {
            for (ModuleInfo m : def.modules()) {
                for (NodeInfo n : m.nodes()) {
                    String name = n.name().toLowerCase(Locale.ROOT);
                    if (name.equals(PROBES) || name.equals(FRAGILE_FOUND) || name.equals(FRAGILE_AVOIDED)) {
                        counters.putIfAbsent(name, new NodeRef(m.name(), n.name()));
                    }
                }
            }
            return null;
        });
    }

    @Override
    public void accept(NetworkEvent event) {
        events.increment();
        if (event instanceof NodeNamedEvent n && n.kind() == NodeKind.DATA
                && n.name().node().toLowerCase(Locale.ROOT).equals(MARGIN_DATA)) {
            marginSource = n.sourceId();
        } else if (event instanceof DataValueEvent d && d.sourceId() == marginSource) {
            if (marginInitialSeen) {
                take(d.value().text());
            }
            marginInitialSeen = true; // the first is the Data's initial value (0), logged before Balance computed one
        } else if (marginSource < 0 && event instanceof RelationValueEvent r) {
            Matcher m = MARGIN.matcher(r.value());
            if (m.matches()) {
                take(m.group(1));
            }
        }
        if (next != null) {
            next.accept(event);
        }
    }

    private void take(String text) {
        double v;
        try {
            v = Double.parseDouble(text);
        } catch (NumberFormatException notANumber) {
            return; // the margin Data holds something else than a number: the margin stays as it was
        }
        if (Double.isNaN(v)) {
            return;
        }
        margin = v;
        if (Double.isNaN(smallest) || v < smallest) {
            smallest = v;
        }
    }

    @Override
    public void flush() {
        if (next != null) {
            next.flush();
        }
    }

    long events() {
        return events.sum();
    }

    DemoFigures figures(RuntimeNetwork network, SensorSnapshot s, double startX, LoopStatistics loop, boolean fallen) {
        return new DemoFigures(s.simTime(), s.groundTruthBodyPosition(0) - startX, margin, smallest,
                count(network, PROBES), count(network, FRAGILE_FOUND), count(network, FRAGILE_AVOIDED),
                s.brokenCellCount(), events.sum(), loop.latencyPercentileNanos(99) / 1e3, loop.overruns(), fallen);
    }

    /** The counter's value, or -1 when the network has no such Data or it holds no number yet. */
    private long count(RuntimeNetwork network, String name) {
        NodeRef ref = counters.get(name);
        if (ref == null) {
            return -1;
        }
        try {
            Value v = network.controller().value(ref);
            return v == null ? -1 : Math.round(v.asDouble());
        } catch (RuntimeException e) {
            return -1; // the module is unloaded at the moment, or the Data holds no number: shown as n/a
        }
    }
}

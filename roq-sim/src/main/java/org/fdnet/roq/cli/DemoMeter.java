package org.fdnet.roq.cli;

import java.util.HashMap;
import java.util.Locale;
import java.util.Map;
import java.util.concurrent.atomic.LongAdder;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.roq.sim.LoopStatistics;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.view.DemoFigures;
import org.fdnet.runtime.RuntimeNetwork;
import org.fdnet.runtime.Value;

/**
 * Measures a demo run from what the network itself says, without depending on its node classes:
 * <pre>
 *   network events ──▶ DemoMeter (EventSink) ──▶ the logger client (when recording)
 *                        │ counts every event; the last "margin X m" a relation reported (KeepBalance's report)
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
    private static final Pattern MARGIN = Pattern.compile("margin (-?\\d+(?:\\.\\d+)?) m.*");

    private final EventSink next;
    private final LongAdder events = new LongAdder();
    private volatile double margin = Double.NaN;
    private volatile double smallest = Double.NaN;
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
        if (event instanceof RelationValueEvent r) {
            Matcher m = MARGIN.matcher(r.value());
            if (m.matches()) {
                double v = Double.parseDouble(m.group(1));
                margin = v;
                if (Double.isNaN(smallest) || v < smallest) {
                    smallest = v;
                }
            }
        }
        if (next != null) {
            next.accept(event);
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

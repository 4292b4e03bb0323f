package org.fdnet.run;

import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.LongAdder;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.netinfo.NodeRef;

/** Counts events by kind and Data values by node, for {@code fdnet run}'s progress and summary. Lock-free. */
final class EventCounter implements EventSink {
    private final Map<String, LongAdder> byKind = new ConcurrentHashMap<>();
    private final Map<Integer, LongAdder> valuesBySource = new ConcurrentHashMap<>();
    private final Map<Integer, NodeRef> names = new ConcurrentHashMap<>();
    private final LongAdder total = new LongAdder();

    @Override
    public void accept(NetworkEvent event) {
        total.increment();
        byKind.computeIfAbsent(event.getClass().getSimpleName(), k -> new LongAdder()).increment();
        if (event instanceof DataValueEvent v) {
            valuesBySource.computeIfAbsent(v.sourceId(), k -> new LongAdder()).increment();
        } else if (event instanceof NodeNamedEvent n) {
            names.put(n.sourceId(), n.name());
        }
    }

    long total() {
        return total.sum();
    }

    Map<String, Long> byKind() {
        Map<String, Long> result = new TreeMap<>();
        byKind.forEach((k, v) -> result.put(k, v.sum()));
        return result;
    }

    long valuesOf(int sourceId) {
        LongAdder a = valuesBySource.get(sourceId);
        return a == null ? 0 : a.sum();
    }

    NodeRef name(int sourceId) {
        return names.get(sourceId);
    }
}

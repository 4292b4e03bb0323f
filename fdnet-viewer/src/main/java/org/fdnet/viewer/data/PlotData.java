package org.fdnet.viewer.data;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.atomic.AtomicLong;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.wire.HistoryColumns;

/**
 * Every series of one viewer, keyed by the logger's source id: a Data holding one number is one series,
 * a Data holding a vector is one series per component ({@code name[0]}, {@code name[1]}, …, created as the
 * components appear). Events of sources not {@link #track tracked}, and values that are not numbers, are
 * counted and otherwise ignored.
 */
public final class PlotData {
    private record Source(String name, String unit, List<Series> components) {
    }

    private final Map<Integer, Source> sources = new ConcurrentHashMap<>();
    private final List<Series> all = new CopyOnWriteArrayList<>();
    private final AtomicLong ignored = new AtomicLong();
    private final AtomicLong accepted = new AtomicLong();
    private volatile UnitBook units = new UnitBook();

    /** Series created from now on take their unit from {@code book} when it knows one (see {@link UnitBook}). */
    public void useUnits(UnitBook book) {
        units = book;
    }

    /** Plots the source's values under {@code name}; tracking a source twice keeps the first. */
    public void track(int sourceId, String name, String unit) {
        sources.computeIfAbsent(sourceId, id -> new Source(name, unit, new CopyOnWriteArrayList<>()));
    }

    public boolean tracks(int sourceId) {
        return sources.containsKey(sourceId);
    }

    public int[] trackedSources() {
        return sources.keySet().stream().mapToInt(Integer::intValue).sorted().toArray();
    }

    /** Adds the event's numbers to its series. */
    public void accept(NetworkEvent event) {
        Source s = event instanceof DataValueEvent ? sources.get(event.sourceId()) : null;
        if (s == null) {
            ignored.incrementAndGet();
            return;
        }
        double[] numbers = SampleDecoder.numbers((DataValueEvent) event);
        if (numbers.length == 0) {
            ignored.incrementAndGet();
            return;
        }
        List<Series> parts = components(s, numbers.length);
        for (int i = 0; i < numbers.length; i++) {
            parts.get(i).append(event.time(), numbers[i]);
        }
        accepted.incrementAndGet();
    }

    /**
     * Adds a history answer: numbers the client already read go straight to their series; any other value
     * (a vector, a boolean) goes through {@link #accept(NetworkEvent)} as an event.
     */
    public void accept(HistoryColumns history) {
        for (int i = 0; i < history.size(); i++) {
            if (!history.hasNumber(i)) {
                accept(history.event(i));
                continue;
            }
            Source s = sources.get(history.sourceId(i));
            if (s == null) {
                ignored.incrementAndGet();
                continue;
            }
            components(s, 1).get(0).append(history.time(i), history.number(i));
            accepted.incrementAndGet();
        }
    }

    /** The source's series, at least {@code count} of them (created as components appear). */
    private List<Series> components(Source s, int count) {
        List<Series> parts = s.components();
        if (parts.size() < count) {
            synchronized (s) {
                while (parts.size() < count) {
                    String name = count == 1 && parts.isEmpty() ? s.name() : s.name() + "[" + parts.size() + "]";
                    Series series = new Series(name, units.unitOf(name, s.unit()));
                    parts.add(series);
                    all.add(series);
                }
            }
        }
        return parts;
    }

    /** Every series, in the order they appeared. */
    public List<Series> series() {
        return all;
    }

    /** The series of one source (empty until its first value). */
    public List<Series> seriesOf(int sourceId) {
        Source s = sources.get(sourceId);
        return s == null ? List.of() : new ArrayList<>(s.components());
    }

    /** Drops every sample (the series and the tracked sources stay). */
    public void clearSamples() {
        all.forEach(Series::clear);
    }

    public long acceptedEvents() {
        return accepted.get();
    }

    public long ignoredEvents() {
        return ignored.get();
    }

    /** The newest sample time over all series, {@link Long#MIN_VALUE} when none. */
    public long lastTime() {
        long t = Long.MIN_VALUE;
        for (Series s : all) {
            t = Math.max(t, s.lastTime());
        }
        return t;
    }

    public long firstTime() {
        long t = Long.MAX_VALUE;
        for (Series s : all) {
            t = Math.min(t, s.firstTime());
        }
        return t;
    }
}

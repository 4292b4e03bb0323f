package org.fdnet.logger.export;

import java.util.List;

/**
 * What of a run to export: the nodes (their source ids; empty for all), whether structure changes go along, and
 * the time range in µs on the run's common clock (inclusive).
 */
public record ExportSelection(List<Integer> sourceIds, boolean structure, long fromMicros, long toMicros) {
    public ExportSelection {
        sourceIds = List.copyOf(sourceIds);
        if (fromMicros > toMicros) {
            throw new IllegalArgumentException("the time range ends (" + toMicros + " µs) before it starts (" + fromMicros + " µs)");
        }
    }

    /** Every node, structure changes, all the time. */
    public static ExportSelection all() {
        return new ExportSelection(List.of(), true, Long.MIN_VALUE, Long.MAX_VALUE);
    }

    public boolean isAllNodes() {
        return sourceIds.isEmpty();
    }

    public boolean isWholeTime() {
        return fromMicros == Long.MIN_VALUE && toMicros == Long.MAX_VALUE;
    }
}

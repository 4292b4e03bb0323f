package org.fdnet.logger.soak;

import java.util.List;
import java.util.Map;
import java.util.NavigableMap;
import java.util.TreeMap;

/**
 * One counted node against the values the soak had acknowledged: each value must be stored {@code expectedCopies}
 * times (by the Data's home host: once). Anomalies — a value stored nowhere, fewer times, or more — are
 * explained when the value was acknowledged around a host's kill -9, unexplained otherwise.
 *
 * @param node        {@code module/node}
 * @param applied     values acknowledged (applied on the home host); -1 for a node the soak does not write
 * @param stored      distinct values stored
 * @param rows        rows stored
 * @param lost        acknowledged values stored nowhere
 * @param gaps        values stored fewer than the expected times
 * @param duplicates  extra copies beyond the expected
 * @param explained   of those anomalies, the ones around a host's kill -9
 * @param unexplained the others: each one a failure
 */
record SequenceCount(String node, long applied, long stored, long rows, long lost, long gaps, long duplicates,
                     long explained, long unexplained) {
    static final long KILL_MARGIN_MILLIS = 3_000;

    /**
     * @param copies       rows per value, from the database
     * @param acknowledged the soak's acknowledged values with their times
     * @param mustHaveAll  whether every acknowledged value must be stored (a Data the soak writes) or only the values
     *                     that were (a Relation's output, which samples its input)
     */
    static SequenceCount of(String node, Map<Long, Integer> copies, List<SequenceWriter.Acknowledged> acknowledged,
                            List<InjectedFault> faults, int expectedCopies, boolean mustHaveAll) {
        // The soak writes 1, 2, 3 …; 0 is the Data's initial value, recorded by every incarnation of its host.
        Map<Long, Integer> written = new TreeMap<>(copies);
        written.keySet().removeIf(v -> v < 1);
        NavigableMap<Long, Long> ackTimes = new TreeMap<>();
        acknowledged.forEach(a -> ackTimes.put(a.value(), a.atMillis()));
        long lost = 0;
        long gaps = 0;
        long duplicates = 0;
        long explained = 0;
        long unexplained = 0;
        long rows = 0;
        for (int c : written.values()) {
            rows += c;
        }
        NavigableMap<Long, Integer> all = new TreeMap<>(written);
        if (mustHaveAll) {
            ackTimes.keySet().forEach(v -> all.putIfAbsent(v, 0));
        }
        for (Map.Entry<Long, Integer> e : all.entrySet()) {
            int c = e.getValue();
            if (c == expectedCopies) {
                continue;
            }
            if (c == 0) {
                lost++;
            } else if (c < expectedCopies) {
                gaps++;
            } else {
                duplicates += c - expectedCopies;
            }
            Map.Entry<Long, Long> ack = ackTimes.floorEntry(e.getKey());
            long at = ack == null ? Long.MIN_VALUE : ack.getValue();
            if (ack != null && faults.stream().anyMatch(f -> f.mayCost(at, KILL_MARGIN_MILLIS))) {
                explained++;
            } else {
                unexplained++;
            }
        }
        return new SequenceCount(node, mustHaveAll ? acknowledged.size() : -1, written.size(), rows, lost, gaps,
                duplicates, explained, unexplained);
    }
}

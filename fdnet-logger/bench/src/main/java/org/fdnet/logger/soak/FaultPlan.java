package org.fdnet.logger.soak;

import java.time.Duration;
import java.util.ArrayList;
import java.util.Collections;
import java.util.IdentityHashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

/**
 * When each fault happens, in cycles. The plain soak's cycle holds one fault of every process kind per minute (the
 * whole run when it is shorter), spaced so that each heals before the next starts; the killed host alternates between
 * the crawler and the flyer. With {@code --apart}, cycles of network faults come between them, in this order:
 * <pre>
 *   network (60 s): crawler/flyer black-holed 5 s, logger black-holed 8 s, naming black-holed 8 s,
 *                   a host throttled to 1 Mbit/s 8 s, 5 % loss on every link 10 s
 *   plain (60 s) ─ partition30 (60 s): a host black-holed 30 s ─ plain ─ loss (75 s): 5 % loss on every link 60 s
 *   ─ plain ─ partition120 (180 s): a host black-holed 120 s ─ plain ─ then again from the start
 * </pre>
 * {@code --cycles} names another order. A cycle is planned only when it fits in the run, so {@code --apart --for 60s}
 * is one network cycle.
 *
 * @param faults the faults in time order, {@code atMillis} after the soak's start
 */
record FaultPlan(List<Planned> faults) {
    static final long MIN_MILLIS = 45_000;
    static final long DATABASE_OUTAGE_MILLIS = 10_000;
    static final double LINK_DROP = 0.2;
    static final int LINK_DELAY_MILLIS = 20;
    static final int LOSS_PERCENT = 5;
    static final int THROTTLE_KBIT_PER_SECOND = 1000;
    private static final String EVERY_HOST = "every host";

    /** One fault of the plan; {@code target} names the host for a host kill, partition or throttle. */
    record Planned(FaultKind kind, long atMillis, long lengthMillis, String target) {
    }

    /** Plans one cycle's faults from {@code start}; {@code n} counts cycles of its kind (to alternate hosts). */
    private interface Planner {
        void plan(long start, long cycle, int n, List<Planned> into);
    }

    /** A cycle: {@code fixedMillis} long (0: a minute, or the whole run when shorter) and what it injects. */
    private record Cycle(long fixedMillis, Planner planner) {
        long length(long total) {
            return fixedMillis > 0 ? fixedMillis : Math.min(60_000, total);
        }
    }

    private static final Cycle PLAIN = new Cycle(0, (start, cycle, n, faults) -> {
        faults.add(new Planned(FaultKind.LINK_FAULTS, start + linkFrom(cycle), linkLength(cycle), "flyer, crawler"));
        faults.add(new Planned(FaultKind.HOST_KILL, start + cycle * 25 / 100, 0, host(n)));
        faults.add(new Planned(FaultKind.LOGGER_KILL, start + cycle * 42 / 100, 0, "logger"));
        faults.add(new Planned(FaultKind.DATABASE_STOP, start + cycle * 56 / 100, DATABASE_OUTAGE_MILLIS, "PostgreSQL"));
        faults.add(new Planned(FaultKind.NAMING_RESTART, start + cycle * 82 / 100, 0, "naming"));
    });

    private static final Cycle NETWORK = new Cycle(60_000, (start, cycle, n, faults) -> {
        faults.add(new Planned(FaultKind.HOST_PARTITION, start + 2_000, 5_000, host(n)));
        faults.add(new Planned(FaultKind.LOGGER_PARTITION, start + 13_000, 8_000, "logger"));
        faults.add(new Planned(FaultKind.NAMING_PARTITION, start + 25_000, 8_000, "naming"));
        faults.add(new Planned(FaultKind.THROTTLE, start + 37_000, 8_000, host(n + 1)));
        faults.add(new Planned(FaultKind.LOSS, start + 47_000, 10_000, EVERY_HOST));
    });

    private static Cycle partition(long outageMillis, long cycleMillis) {
        return new Cycle(cycleMillis, (start, cycle, n, faults) ->
                faults.add(new Planned(FaultKind.HOST_PARTITION, start + 2_000, outageMillis, host(n + 1))));
    }

    private static final Cycle LOSS_MINUTE = new Cycle(75_000, (start, cycle, n, faults) ->
            faults.add(new Planned(FaultKind.LOSS, start + 2_000, 60_000, EVERY_HOST)));

    /** The cycles {@code --cycles} may name. */
    static final Map<String, Cycle> CYCLES = cycles();

    /** The order of {@code --apart}'s cycles unless {@code --cycles} gives another. */
    static final List<String> APART_ORDER = List.of("network", "plain", "partition30", "plain", "loss", "plain",
            "partition120", "plain");

    private static Map<String, Cycle> cycles() {
        Map<String, Cycle> c = new LinkedHashMap<>();
        c.put("network", NETWORK);
        c.put("plain", PLAIN);
        c.put("partition30", partition(30_000, 60_000));
        c.put("loss", LOSS_MINUTE);
        c.put("partition120", partition(120_000, 180_000));
        return Collections.unmodifiableMap(c);
    }

    /**
     * @throws IllegalArgumentException when {@code duration} is too short for every kind
     */
    static FaultPlan of(Duration duration) {
        long total = duration.toMillis();
        if (total < MIN_MILLIS) {
            throw new IllegalArgumentException("--for must be at least " + MIN_MILLIS / 1000 + "s to fit every fault"
                    + " kind with time to heal, was " + duration.toSeconds() + "s");
        }
        List<Planned> faults = new ArrayList<>();
        long cycle = PLAIN.length(total);
        int n = 0;
        for (long start = 0; start + cycle <= total; start += cycle, n++) {
            PLAIN.planner().plan(start, cycle, n, faults);
        }
        return new FaultPlan(List.copyOf(faults));
    }

    /**
     * The plan of {@code fdnet soak --apart}: the cycles named in {@code order} ({@link #CYCLES}), again and again,
     * while they fit.
     *
     * @throws IllegalArgumentException when {@code duration} is shorter than the first cycle, or a name is unknown
     */
    static FaultPlan apart(Duration duration, List<String> order) {
        long total = duration.toMillis();
        if (order.isEmpty()) {
            throw new IllegalArgumentException("--cycles names no cycle; known: " + String.join(", ", CYCLES.keySet()));
        }
        for (String name : order) {
            if (!CYCLES.containsKey(name)) {
                throw new IllegalArgumentException("--cycles: no cycle '" + name + "'; known: "
                        + String.join(", ", CYCLES.keySet()));
            }
        }
        long needed = order.get(0).equals("plain") ? MIN_MILLIS : CYCLES.get(order.get(0)).length(total);
        if (total < needed) {
            throw new IllegalArgumentException("--for must be at least " + needed / 1000 + "s to fit the " + order.get(0)
                    + " cycle with time to heal, was " + duration.toSeconds() + "s");
        }
        List<Planned> faults = new ArrayList<>();
        Map<Cycle, Integer> seen = new IdentityHashMap<>();
        long start = 0;
        for (int i = 0; ; i++) {
            Cycle c = CYCLES.get(order.get(i % order.size()));
            long length = c.length(total);
            if (start + length > total) {
                break;
            }
            int n = seen.merge(c, 1, Integer::sum) - 1;
            c.planner().plan(start, length, n, faults);
            start += length;
        }
        return new FaultPlan(List.copyOf(faults));
    }

    private static String host(int n) {
        return n % 2 == 0 ? "crawler" : "flyer";
    }

    static long linkFrom(long cycle) {
        return cycle * 6 / 100;
    }

    static long linkLength(long cycle) {
        return cycle * 14 / 100;
    }

    /** What the hosts' link fault switch file holds while link faults are on. */
    static String linkFaultsOn() {
        return "drop=" + LINK_DROP + ",delay=" + LINK_DELAY_MILLIS;
    }
}

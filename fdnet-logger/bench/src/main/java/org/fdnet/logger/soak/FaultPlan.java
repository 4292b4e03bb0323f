package org.fdnet.logger.soak;

import java.time.Duration;
import java.util.ArrayList;
import java.util.List;

/**
 * When each fault happens: one cycle of every kind per minute (the whole run when it is shorter), kinds spaced so
 * that each heals before the next starts; the killed host alternates between the crawler and the flyer.
 *
 * @param cycleMillis length of one cycle
 * @param faults      the faults in time order, {@code atMillis} after the soak's start
 */
record FaultPlan(long cycleMillis, List<Planned> faults) {
    static final long MIN_MILLIS = 45_000;
    static final long DATABASE_OUTAGE_MILLIS = 10_000;
    static final double LINK_DROP = 0.2;
    static final int LINK_DELAY_MILLIS = 20;

    /** One fault of the plan; {@code target} names the host for a host kill. */
    record Planned(FaultKind kind, long atMillis, long lengthMillis, String target) {
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
        long cycle = Math.min(60_000, total);
        List<Planned> faults = new ArrayList<>();
        int n = 0;
        for (long start = 0; start + cycle <= total; start += cycle, n++) {
            faults.add(new Planned(FaultKind.LINK_FAULTS, start + linkFrom(cycle), linkLength(cycle), "flyer, crawler"));
            faults.add(new Planned(FaultKind.HOST_KILL, start + cycle * 25 / 100, 0, n % 2 == 0 ? "crawler" : "flyer"));
            faults.add(new Planned(FaultKind.LOGGER_KILL, start + cycle * 42 / 100, 0, "logger"));
            faults.add(new Planned(FaultKind.DATABASE_STOP, start + cycle * 56 / 100, DATABASE_OUTAGE_MILLIS, "PostgreSQL"));
            faults.add(new Planned(FaultKind.NAMING_RESTART, start + cycle * 82 / 100, 0, "naming"));
        }
        return new FaultPlan(cycle, List.copyOf(faults));
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

package org.fdnet.roq.bench;

import java.lang.management.GarbageCollectorMXBean;
import java.lang.management.ManagementFactory;
import java.time.LocalTime;
import java.time.ZoneOffset;
import java.util.List;
import java.util.Locale;
import org.fdnet.runtime.Value;

/**
 * Where one stimulus's answer spent its time (bench roq (b) {@code --trace}): wall-clock moments, taken by value
 * observers on the committing thread, of each stage from the snapshot that showed the stimulus to the command the
 * loop applied, and the thread each ran on.
 *
 * <pre>
 *  tick S published ─▶ bridge reads + commits S (attitude/gyro observed) ─▶ reflex writes (press observed)
 *     ─▶ JointTargets written (observed; the bridge sends it from the same commit) ─▶ loop applies it at tick A
 * </pre>
 *
 * The loop's tick clock is not read directly: a snapshot of tick n is published about {@code base + n} ms, where
 * {@code base} is the smallest {@code nanoTime − n ms} of the sensor values committed since the stimulus was armed
 * (the quickest read), so each stage is given in ms after tick S's publication, and the deadline to make tick A is
 * about {@code A − S} ms after it. Whether the reflex already held a correction (a brace under way) when S came is
 * said too. With it: the garbage collections counted between the stimulus and the answer (all
 * collectors), the longest the logger client's {@code accept} took inside a commit from the stimulus to the targets
 * (the logger's share of the commit path), and the wall time (UTC, to match a {@code -Xlog:gc*,safepoint} file).
 */
final class AnswerStages {
    private static final List<GarbageCollectorMXBean> COLLECTORS = ManagementFactory.getGarbageCollectorMXBeans();

    private volatile long base = Long.MAX_VALUE;
    private volatile long shownTick = -1;
    private volatile long shown;
    private volatile String shownOn;
    private volatile boolean pressHeld;
    private volatile boolean heldAtShown;
    private volatile long reflex;
    private volatile String reflexOn;
    private volatile long targets;
    private volatile String targetsOn;
    private volatile long sinkMax;
    private volatile long sinkOver100us;
    private long gcCount;
    private long gcMillis;
    private LocalTime wall;

    /** Any sensor value of tick {@code tick} committed now: tightens the tick clock. */
    void sensorCommitted(long tick) {
        long b = System.nanoTime() - tick * 1_000_000L;
        if (b < base) {
            base = b;
        }
    }

    /**
     * A new stimulus: forgets the last one's stages and the tick clock (the loop skips a deadline it overran, so
     * the clock is taken afresh from the snapshots committed between now and the stimulus's).
     */
    void arm() {
        base = Long.MAX_VALUE;
        sinkMax = 0;
        sinkOver100us = 0;
        shownTick = -1;
        reflex = 0;
        targets = 0;
        gcCount = collections();
        gcMillis = collectionMillis();
        wall = LocalTime.now(ZoneOffset.UTC);
    }

    /** An event took {@code nanos} in the logger client's {@code accept} (called inside the commit). */
    void sinkTook(long nanos) {
        if (targets == 0) {
            if (nanos > sinkMax) {
                sinkMax = nanos;
            }
            if (nanos > 100_000) {
                sinkOver100us++;
            }
        }
    }

    /** The snapshot of {@code tick} first showed the stimulus (called from its commit). */
    void shown(long tick) {
        shown = System.nanoTime();
        shownOn = Thread.currentThread().getName();
        heldAtShown = pressHeld;
        shownTick = tick;
    }

    /** The reflex wrote {@code correction}, computed from its tick. */
    void reflexWrote(Value correction) {
        if (shownTick >= 0 && correction.tick() >= shownTick && reflex == 0) {
            reflex = System.nanoTime();
            reflexOn = Thread.currentThread().getName();
        }
        boolean held = false;
        for (int i = 0; i < correction.length(); i++) {
            held |= correction.element(i) != 0;
        }
        pressHeld = held;
    }

    /** JointTargets took a value computed from {@code tick}. */
    void targetsWritten(long tick) {
        if (shownTick >= 0 && tick >= shownTick && targets == 0) {
            targets = System.nanoTime();
            targetsOn = Thread.currentThread().getName();
        }
    }

    /** One line: the latency and each stage in ms after tick S's publication, with its thread. */
    String describe(long latency, long appliedTick) {
        long published = base + shownTick * 1_000_000L;
        return String.format(Locale.ROOT, "  %s S=%d latency %d ms: committed +%.3f ms (%s), reflex %s%s, targets %s,"
                        + " applied at tick %d (deadline ~+%d ms); %d GC (%d ms); logger accept until the targets: max"
                        + " %.3f ms, %d over 0.1 ms", wall, shownTick, latency,
                (shown - published) / 1e6, shownOn, stage(reflex, reflexOn, published),
                heldAtShown ? " (a correction already held at S)" : "", stage(targets, targetsOn,
                        published), appliedTick, appliedTick - shownTick, collections() - gcCount,
                collectionMillis() - gcMillis, sinkMax / 1e6, sinkOver100us);
    }

    private static String stage(long at, String on, long published) {
        return at == 0 ? "-" : String.format(Locale.ROOT, "+%.3f ms (%s)", (at - published) / 1e6, on);
    }

    private static long collections() {
        long n = 0;
        for (GarbageCollectorMXBean gc : COLLECTORS) {
            n += Math.max(0, gc.getCollectionCount());
        }
        return n;
    }

    private static long collectionMillis() {
        long n = 0;
        for (GarbageCollectorMXBean gc : COLLECTORS) {
            n += Math.max(0, gc.getCollectionTime());
        }
        return n;
    }
}

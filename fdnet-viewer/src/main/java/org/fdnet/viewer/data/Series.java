package org.fdnet.viewer.data;

import java.util.Arrays;

/**
 * One plotted line: the samples (time in µs since the epoch, value) of one Data — or of one component of a
 * Data holding several doubles — with its name and unit. Appends come from the network thread, reads from
 * the painter: both lock this object. Keeps at most {@link #MAX_SAMPLES}; beyond that the oldest quarter
 * is dropped (10 min at 1 kHz; 50 such series hold about 0.5 GB).
 */
public final class Series {
    public static final int MAX_SAMPLES = 600_000;

    private final String name;
    private final String unit;
    private long[] times = new long[1024];
    private double[] values = new double[1024];
    private int start;
    private int end;
    private long appended;

    public Series(String name, String unit) {
        this.name = name;
        this.unit = unit == null ? "" : unit;
    }

    public String name() {
        return name;
    }

    /** The unit, {@code ""} when none was given. */
    public String unit() {
        return unit;
    }

    public synchronized void append(long time, double value) {
        if (end == times.length) {
            makeRoom();
        }
        times[end] = time;
        values[end] = value;
        end++;
        appended++;
    }

    private void makeRoom() {
        int size = end - start;
        if (size >= MAX_SAMPLES) {
            start += size / 4;
            size = end - start;
        }
        int capacity = times.length;
        if (size > capacity / 2) {
            capacity = Math.min(MAX_SAMPLES + MAX_SAMPLES / 2, capacity * 2);
        }
        long[] t = new long[capacity];
        double[] v = new double[capacity];
        System.arraycopy(times, start, t, 0, size);
        System.arraycopy(values, start, v, 0, size);
        times = t;
        values = v;
        start = 0;
        end = size;
    }

    public synchronized int size() {
        return end - start;
    }

    /** Every sample ever appended, including those dropped since. */
    public synchronized long appended() {
        return appended;
    }

    public synchronized void clear() {
        start = 0;
        end = 0;
    }

    /** The newest sample's time, or {@link Long#MIN_VALUE} when empty. */
    public synchronized long lastTime() {
        return end == start ? Long.MIN_VALUE : times[end - 1];
    }

    public synchronized long firstTime() {
        return end == start ? Long.MAX_VALUE : times[start];
    }

    /** The samples with {@code from <= time <= to}, copied. */
    public synchronized Samples range(long from, long to) {
        int a = lowerBound(from);
        int b = lowerBound(to == Long.MAX_VALUE ? to : to + 1);
        return new Samples(Arrays.copyOfRange(times, a, b), Arrays.copyOfRange(values, a, b));
    }

    /** The sample nearest to {@code time} (or null when empty). */
    public synchronized Sample nearest(long time) {
        if (end == start) {
            return null;
        }
        int i = lowerBound(time);
        if (i == end || (i > start && time - times[i - 1] <= times[i] - time)) {
            i--;
        }
        return new Sample(times[i], values[i]);
    }

    /**
     * The value the Data held at {@code time}: its newest sample at or before it (a Data keeps its value until it is
     * written again), or null when its first sample is later.
     */
    public synchronized Sample heldAt(long time) {
        int i = lowerBound(time == Long.MAX_VALUE ? time : time + 1) - 1;
        return i < start ? null : new Sample(times[i], values[i]);
    }

    /** Visits the samples from one before {@code from} to one after {@code to} (so lines reach the edges). */
    public synchronized void visit(long from, long to, SampleVisitor visitor) {
        int a = Math.max(start, lowerBound(from) - 1);
        int b = Math.min(end, lowerBound(to) + 1);
        for (int i = a; i < b; i++) {
            visitor.sample(times[i], values[i]);
        }
    }

    private int lowerBound(long time) {
        int lo = start;
        int hi = end;
        while (lo < hi) {
            int mid = (lo + hi) >>> 1;
            if (times[mid] < time) {
                lo = mid + 1;
            } else {
                hi = mid;
            }
        }
        return lo;
    }

    /** Receives samples in time order. */
    @FunctionalInterface
    public interface SampleVisitor {
        void sample(long time, double value);
    }

    public record Sample(long time, double value) {
    }

    public record Samples(long[] times, double[] values) {
        public int size() {
            return times.length;
        }
    }

    @Override
    public String toString() {
        return unit.isEmpty() ? name : name + " [" + unit + "]";
    }
}

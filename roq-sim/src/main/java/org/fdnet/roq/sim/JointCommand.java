package org.fdnet.roq.sim;

/**
 * What the loop is told to do: 12 joint targets (rad) and, optionally, 4 wheel speeds (rad/s). Owned by the caller
 * and reused; {@link RoqSimulator#send(JointCommand)} copies it into the command slot. The loop clamps targets to
 * the joint limits and ignores NaN or infinite values (keeping the previous target), counting both in
 * {@link LoopStatistics}; a command based on a snapshot older than {@link SharedBlockLayout#STALE_TICKS} ticks
 * is ignored and counted stale.
 */
public final class JointCommand {
    private final double[] targets = new double[RoqGeometry.JOINTS];
    private final double[] wheelSpeeds = new double[RoqGeometry.LEGS];
    private boolean wheelsEnabled;
    private long basedOnTick = -1;
    private long sourceTick = -1;

    /** A command holding the standing pose, wheels braked. */
    public JointCommand() {
        RoqGeometry.standingTargets(targets);
    }

    /** Sets joint {@code j}'s target, rad. Returns this. */
    public JointCommand target(int j, double radians) {
        targets[j] = radians;
        return this;
    }

    /** Sets all 12 targets from {@code radians}. Returns this. */
    public JointCommand targets(double[] radians) {
        System.arraycopy(radians, 0, targets, 0, RoqGeometry.JOINTS);
        return this;
    }

    /** Joint {@code j}'s target, rad. */
    public double target(int j) {
        return targets[j];
    }

    /**
     * Drives leg {@code leg}'s wheel at {@code radiansPerSecond} (positive rolls the foot forward, +x, in the
     * standing pose) and enables the wheels. Returns this.
     */
    public JointCommand wheelSpeed(int leg, double radiansPerSecond) {
        wheelSpeeds[leg] = radiansPerSecond;
        wheelsEnabled = true;
        return this;
    }

    /** Leg {@code leg}'s wheel speed, rad/s. */
    public double wheelSpeed(int leg) {
        return wheelSpeeds[leg];
    }

    /** Whether the wheels are driven (else braked). */
    public boolean wheelsEnabled() {
        return wheelsEnabled;
    }

    /** Drives ({@code true}) or brakes ({@code false}) the wheels. Returns this. */
    public JointCommand wheelsEnabled(boolean enabled) {
        wheelsEnabled = enabled;
        return this;
    }

    /**
     * The tick of the snapshot this command was computed from; −1 (the default) lets {@link RoqSimulator#send}
     * use the tick of the last snapshot read. Returns this.
     */
    public JointCommand basedOnTick(long tick) {
        basedOnTick = tick;
        return this;
    }

    /** The tick this command was computed from, or −1. */
    public long basedOnTick() {
        return basedOnTick;
    }

    /**
     * The newest sensor snapshot the command was computed from, when that differs from {@link #basedOnTick()} (the
     * freshness the loop's staleness check uses): a network's command computed now may rest on an older reading.
     * 0: computed from no snapshot (the loop leaves it out of the reflex figures); −1 (the default): the same as
     * {@link #basedOnTick()}. Returns this.
     */
    public JointCommand sourceTick(long tick) {
        sourceTick = tick;
        return this;
    }

    /** See {@link #sourceTick(long)}. */
    public long sourceTick() {
        return sourceTick;
    }
}

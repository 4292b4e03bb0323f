package org.fdnet.roq.bridge;

import java.util.List;
import java.util.Locale;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.roq.node.GaitPhase;
import org.fdnet.roq.sim.FragileCell;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.engine.RuntimeNetwork;

/**
 * Measures a run on a course by ground truth (allowed for measuring, never for control), sampled every 10 ms by
 * the caller: how far RoQ strayed from its course line (the straight line ahead of where it started) and from its
 * heading, each averaged over {@link #WINDOW} samples, one crawl cycle (the body sways ±0.15 m and ±0.1 rad within
 * a cycle by design), and which fragile cells broke under a probe and which under a loaded foot.
 *
 * <pre>
 *   snapshot (ground truth y, yaw, feet, broken cells) ─┐
 *   the network's "gait phase" {leg, swing, probe}      ┴─▶ sample() ──▶ track / heading errors, max and at the end
 *                                                                      └▶ BreakthroughCauses: probe-broken cells /
 *                                                                         loaded-foot breakthroughs and whose foot
 * </pre>
 *
 * <p>A cell that breaks under the probed foot while the gait phase says its probe presses (its third element above
 * 0) was broken by the probe, on purpose; any other — under another foot during a press too — was broken under a foot
 * that had been accepted and loaded ({@link BreakthroughCauses}).
 */
public final class CourseMeter {
    /** Samples (10 ms each) over which the track and heading are averaged: 4.5 s, roq-rubble's crawl cycle. */
    public static final int WINDOW = 450;
    /** The Data telling the gait's phase {leg, swinging, probing}, in the module {@link #PHASE_MODULE}. */
    static final String PHASE = "gait phase";
    static final String PHASE_MODULE = "main";

    private final double y0;
    private final double yaw0;
    private final double[] lastY = new double[WINDOW];
    private final double[] lastYaw = new double[WINDOW];
    private double sumY;
    private double sumYaw;
    private int samples;
    private double maxTrack;
    private double maxHeading;
    /** Which cells the probes broke and whose foot each loaded-foot breakthrough was under. */
    private final BreakthroughCauses causes;
    private final double[] foot = new double[3];
    private final double[] world = new double[3];
    private final double[] feet = new double[2 * RoqGeometry.LEGS];
    private final boolean[] brokenNow;

    /**
     * Starts measuring from {@code start} on a course with fragile {@code cells} (the course's, in their order; cells
     * broken already are left out): its position across and its heading are the course line's.
     */
    public CourseMeter(SensorSnapshot start, List<FragileCell> cells) {
        this(start.groundTruthBodyPosition(1), start.groundTruthYaw(), cells);
        causes.alreadyBroken(brokenCells(start));
    }

    /** Starts measuring from the course line at {@code y0} heading {@code yaw0} on a course with fragile {@code cells}. */
    CourseMeter(double y0, double yaw0, List<FragileCell> cells) {
        this.y0 = y0;
        this.yaw0 = yaw0;
        this.causes = new BreakthroughCauses(cells);
        this.brokenNow = new boolean[cells.size()];
    }

    /** Takes one sample (every 10 ms): {@code s} now and the network whose gait phase tells a probe's press. */
    public void sample(SensorSnapshot s, RuntimeNetwork network) {
        if (causes.hasCells()) {
            GaitPhase phase = GaitPhase.of(phase(network));
            causes.sample(feetInWorld(s), phase.upLeg(), brokenCells(s), phase.proving());
        }
        sample(s.groundTruthBodyPosition(1), s.groundTruthYaw());
    }

    /** The feet's centres in the world frame (x, y per foot) by ground truth and the measured joint angles. */
    private double[] feetInWorld(SensorSnapshot s) {
        for (int leg = 0; leg < RoqGeometry.LEGS; leg++) {
            RoqGeometry.footInBody(leg, s.jointAngle(3 * leg), s.jointAngle(3 * leg + 1), s.jointAngle(3 * leg + 2), foot);
            s.groundTruthToWorld(foot, world);
            feet[2 * leg] = world[0];
            feet[2 * leg + 1] = world[1];
        }
        return feet;
    }

    private boolean[] brokenCells(SensorSnapshot s) {
        for (int i = 0; i < brokenNow.length; i++) {
            brokenNow[i] = s.isCellBroken(i);
        }
        return brokenNow;
    }

    /** One sample of the track and heading: the body at {@code y} heading {@code yaw} (ground truth). */
    void sample(double y, double yaw) {
        int slot = samples % WINDOW;
        double across = y - y0;
        sumY += across - lastY[slot];
        lastY[slot] = across;
        double turned = angle(yaw - yaw0);
        sumYaw += turned - lastYaw[slot];
        lastYaw[slot] = turned;
        samples++;
        if (samples >= WINDOW) {
            maxTrack = Math.max(maxTrack, Math.abs(endTrack()));
            maxHeading = Math.max(maxHeading, Math.abs(endHeading()));
        }
    }

    /** Whether {@code network}'s gait phase says a probe presses now (false without such a Data). */
    static boolean probing(RuntimeNetwork network) {
        return presses(phase(network));
    }

    /** Whether {@code phase} says a probe presses or a foothold is being proved (false for null). */
    private static boolean presses(Value phase) {
        return GaitPhase.of(phase).proving();
    }

    /** {@code network}'s gait phase, or null without one. */
    private static Value phase(RuntimeNetwork network) {
        try {
            return network.controller().value(NodeRef.parse(PHASE, PHASE_MODULE));
        } catch (RuntimeException notLoaded) {
            return null; // no gait phase (unloaded, or another network): no press is known, the break counts as loaded
        }
    }

    /** The largest |y − y at the start| averaged over a cycle, m (0 before the first whole cycle). */
    public double maxTrackError() {
        return maxTrack;
    }

    /** The largest |yaw − yaw at the start| averaged over a cycle, rad (0 before the first whole cycle). */
    public double maxHeadingError() {
        return maxHeading;
    }

    /** y − y at the start averaged over the last cycle (or the samples so far), m; signed (left positive). */
    public double endTrack() {
        return samples == 0 ? 0 : sumY / Math.min(samples, WINDOW);
    }

    /** yaw − yaw at the start averaged over the last cycle (or the samples so far), rad; signed. */
    public double endHeading() {
        return samples == 0 ? 0 : sumYaw / Math.min(samples, WINDOW);
    }

    /** Cells broken under the probed foot while its probe pressed, on purpose. */
    public int probeBroken() {
        return causes.probeBroken();
    }

    /** Every other broken cell: under a foot that had been accepted and loaded. */
    public int loadedBreakthroughs() {
        return causes.loaded();
    }

    /** Whose foot the loaded-foot breakthroughs were under. */
    public BreakthroughCauses causes() {
        return causes;
    }

    /** The one summary line of these figures. */
    public String summary() {
        return String.format(Locale.ROOT, "cells broken by probes %d, loaded-foot breakthroughs %d%s; off the course"
                        + " line max %.3f m, at the end %.3f m; heading error max %.3f rad, at the end %.3f rad"
                        + " (ground truth, each averaged over a %.1f s crawl cycle)", probeBroken(), loadedBreakthroughs(),
                loadedBreakthroughs() == 0 ? "" : " (" + causes.summary() + ")",
                maxTrack, endTrack(), maxHeading, endHeading(), WINDOW / 100.0);
    }

    /** {@code a} wrapped to (−π, π]. */
    public static double angle(double a) {
        return Math.atan2(Math.sin(a), Math.cos(a));
    }
}

package org.fdnet.roq.sim;

import java.util.List;
import java.util.Locale;

import static org.fdnet.roq.sim.RoqGeometry.*;

/**
 * Writes the MJCF (MuJoCo's XML model) of the RoQ on a course from {@link RoqGeometry}: the one place the model's
 * numbers come from. The heightfield's grid is declared here and filled from C with {@link Heightfield}'s heights
 * after loading (MuJoCo 2.2.2 zero-fills a heightfield given by {@code nrow}/{@code ncol}).
 *
 * <p>Bodies: {@code body} (free joint {@code root}) → per leg {@code L_coxa} (joint {@code L_yaw}) →
 * {@code L_thigh} ({@code L_lift}) → {@code L_shank} ({@code L_knee}) → {@code L_wheel} ({@code L_wheel}, geom
 * {@code L_foot}). Joint order in qpos: root, then per leg yaw, lift, knee, wheel; the C side checks it.
 * The world has a {@code floor} plane at the heightfield's lowest point, under and around the course.
 * Collisions: robot geoms only touch the terrain, the floor and fragile cells, never each other. Robot geoms are in geom
 * group 1, the ground in group 0: the range sensors cast their rays at group 0 only.
 */
public final class MjcfWriter {
    /** Collision bits: robot geoms have contype 1 / conaffinity 2, ground geoms contype 2 / conaffinity 1. */
    private static final String ROBOT = " contype=\"1\" conaffinity=\"2\" group=\"1\"";
    private static final String GROUND = " contype=\"2\" conaffinity=\"1\"";

    private MjcfWriter() {
    }

    /** The model of the RoQ set down at the course's start, {@code dropHeight} above standing height. */
    public static String write(Course course, Heightfield terrain, double dropHeight) {
        StringBuilder x = new StringBuilder(8192);
        double elevation = terrain.elevationRange();
        x.append("<mujoco model=\"roq\">\n");
        x.append("  <compiler angle=\"radian\" autolimits=\"true\"/>\n");
        x.append(f("  <option timestep=\"%s\" integrator=\"Euler\" gravity=\"0 0 -9.81\"/>\n", TIMESTEP));
        x.append("  <default>\n    <geom friction=\"1.0 0.005 0.0001\" solref=\"0.005 1\"/>\n  </default>\n");
        x.append("  <asset>\n");
        x.append(f("    <hfield name=\"terrain\" nrow=\"%d\" ncol=\"%d\" size=\"%s %s %s 0.1\"/>\n",
                terrain.rows(), terrain.cols(), course.length() / 2, course.width() / 2, elevation));
        x.append("  </asset>\n  <worldbody>\n");
        x.append(f("    <geom name=\"terrain\" type=\"hfield\" hfield=\"terrain\" pos=\"0 0 %s\"%s/>\n",
                terrain.minHeight(), GROUND));
        // The floor: an endless plane at the heightfield's lowest point, so a robot that leaves the course lands
        // on it instead of falling forever (the heightfield has no ground outside its extent). Inside the
        // course the heightfield is at or above it. The range sensors' rays do not see it (roq_ray.c).
        x.append(f("    <geom name=\"floor\" type=\"plane\" size=\"0 0 1\" pos=\"0 0 %s\"%s/>\n",
                terrain.minHeight(), GROUND));
        List<FragileCell> cells = course.fragileCells();
        for (int i = 0; i < cells.size(); i++) {
            FragileCell c = cells.get(i);
            double halfZ = (c.height() + 0.02) / 2;
            x.append(f("    <geom name=\"fragile_%d\" type=\"box\" pos=\"%s %s %s\" size=\"%s %s %s\"%s/>\n",
                    i, c.x(), c.y(), terrain.cellTop(i) - halfZ, c.sizeX() / 2, c.sizeY() / 2, halfZ, GROUND));
        }
        double z = groundUnderFeet(course, terrain) + standingHeight() + dropHeight + 0.001;
        x.append(f("    <body name=\"body\" pos=\"%s %s %s\">\n", course.startX(), course.startY(), z));
        x.append("      <freejoint name=\"root\"/>\n");
        x.append(f("      <geom name=\"body\" type=\"box\" size=\"%s %s %s\" mass=\"%s\"%s/>\n",
                BODY_LENGTH / 2, BODY_WIDTH / 2, BODY_HEIGHT / 2, BODY_MASS, ROBOT));
        x.append("      <site name=\"imu\" pos=\"0 0 0\"/>\n");
        for (int leg = 0; leg < LEGS; leg++) {
            leg(x, leg);
        }
        x.append("    </body>\n  </worldbody>\n");
        // The IMU (assumed part): MuJoCo's own gyro and accelerometer at the body's centre; C adds noise and bias.
        x.append("  <sensor>\n    <gyro name=\"imu_gyro\" site=\"imu\"/>\n");
        x.append("    <accelerometer name=\"imu_accel\" site=\"imu\"/>\n  </sensor>\n</mujoco>\n");
        return x.toString();
    }

    /** The highest ground (terrain or fragile cell top) under the body centre and the four standing feet. */
    static double groundUnderFeet(Course course, Heightfield terrain) {
        double highest = terrain.heightAt(course.startX(), course.startY());
        double[] foot = new double[3];
        for (int leg = 0; leg < LEGS; leg++) {
            footInBody(leg, STANDING_POSE[0], STANDING_POSE[1], STANDING_POSE[2], foot);
            double x = course.startX() + foot[0];
            double y = course.startY() + foot[1];
            boolean onCell = false;
            for (int i = 0; i < course.fragileCells().size(); i++) {
                if (course.fragileCells().get(i).contains(x, y)) {
                    highest = Math.max(highest, terrain.cellTop(i));
                    onCell = true;
                }
            }
            if (!onCell) {
                highest = Math.max(highest, terrain.heightAt(x, y));
            }
        }
        return highest;
    }

    private static void leg(StringBuilder x, int leg) {
        String n = LEG_NAMES[leg];
        double[] hip = HIP_POSITION[leg];
        String joint = f(" armature=\"%s\" damping=\"%s\" frictionloss=\"%s\"", armature(), JOINT_DAMPING, JOINT_FRICTION);
        x.append(f("      <body name=\"%s_coxa\" pos=\"%s %s %s\" euler=\"0 0 %s\">\n", n, hip[0], hip[1], hip[2],
                HIP_YAW_OFFSET[leg]));
        x.append(f("        <joint name=\"%s_yaw\" axis=\"0 0 1\" range=\"%s %s\"%s/>\n", n, JOINT_MIN[0], JOINT_MAX[0], joint));
        x.append(f("        <geom type=\"capsule\" fromto=\"0 0 0 %s 0 0\" size=\"0.025\" mass=\"%s\"%s/>\n",
                COXA_LENGTH, COXA_MASS, ROBOT));
        x.append(f("        <body name=\"%s_thigh\" pos=\"%s 0 0\">\n", n, COXA_LENGTH));
        x.append(f("          <joint name=\"%s_lift\" axis=\"0 -1 0\" range=\"%s %s\"%s/>\n", n, JOINT_MIN[1], JOINT_MAX[1], joint));
        x.append(f("          <geom type=\"capsule\" fromto=\"0 0 0 %s 0 0\" size=\"0.02\" mass=\"%s\"%s/>\n",
                THIGH_LENGTH, THIGH_MASS, ROBOT));
        x.append(f("          <body name=\"%s_shank\" pos=\"%s 0 0\">\n", n, THIGH_LENGTH));
        x.append(f("            <joint name=\"%s_knee\" axis=\"0 1 0\" range=\"%s %s\"%s/>\n", n, JOINT_MIN[2], JOINT_MAX[2], joint));
        x.append(f("            <geom type=\"capsule\" fromto=\"0 0 0 %s 0 0\" size=\"0.015\" mass=\"%s\"%s/>\n",
                SHANK_LENGTH - FOOT_RADIUS, SHANK_MASS, ROBOT));
        x.append(f("            <body name=\"%s_wheel\" pos=\"%s 0 0\">\n", n, SHANK_LENGTH));
        // The axle points out along the leg (the shank frame's z when the shank hangs down); right legs point the
        // other way so that a positive wheel speed rolls every foot forward (+x) in the standing pose.
        x.append(f("              <joint name=\"%s_wheel\" axis=\"0 0 %d\" armature=\"0.002\" damping=\"0.001\"/>\n", n,
                HIP_YAW_OFFSET[leg] > 0 ? 1 : -1));
        x.append(f("              <geom name=\"%s\" type=\"sphere\" size=\"%s\" mass=\"%s\"%s/>\n",
                footName(leg), FOOT_RADIUS, FOOT_MASS, ROBOT));
        x.append("            </body>\n          </body>\n        </body>\n      </body>\n");
    }

    private static String f(String format, Object... args) {
        return String.format(Locale.ROOT, format, args);
    }
}

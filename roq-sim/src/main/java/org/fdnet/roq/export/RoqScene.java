package org.fdnet.roq.export;

import java.io.IOException;
import java.util.List;
import org.fdnet.logger.export.ExportRow;
import org.fdnet.logger.export.RunScene;
import org.fdnet.roq.sim.FragileCell;
import org.fdnet.roq.sim.RoqGeometry;

/**
 * RoQ's recorded Datas turned into what the demo window draws, as Foxglove messages: the body's pose, its legs
 * by forward kinematics of the recorded joint angles ({@link RoqGeometry#legInBody}), the feet (green when their
 * sole bears load), each sole's force as an upward arrow, and the course's fragile cells — a cell is drawn broken
 * from the moment a recorded foot on it pressed beyond its strength for {@link FragileCell#BREAK_HOLD_SECONDS}
 * (the simulator's rule, applied to the recorded feet every 10 ms; the heading is the network's own estimate, so near a cell's
 * edge the verdict may differ from the simulator's). The robot is drawn at most {@value #FRAMES_PER_SECOND} times a
 * second of recorded time.
 */
final class RoqScene implements RunScene {
    static final int FRAMES_PER_SECOND = 30;
    /** A sole bearing more than this is drawn in contact, N. */
    static final double CONTACT_NEWTONS = 5;
    /** Arrow length per newton of sole force, m/N (the robot's weight on one foot ≈ 0.4 m). */
    static final double ARROW_METRES_PER_NEWTON = 1.0 / 450;
    private static final long FRAME_NANOS = 1_000_000_000L / FRAMES_PER_SECOND;
    /** The break rule is checked every 10 ms of recorded time: ten times within a cell's hold of 0.1 s. */
    private static final long CHECK_NANOS = 10_000_000L;
    private static final double[] ARROW_UP = {0, -Math.sqrt(0.5), 0, Math.sqrt(0.5)}; // x axis turned onto z

    private final RoqNodes nodes;
    private final List<FragileCell> cells;
    private final boolean[] broken;
    private final long[] pressedSince;
    private final double[] position = new double[3];
    private final double[] attitude = new double[2];
    private final double[] angles = new double[RoqGeometry.JOINTS];
    private final double[] forces = new double[RoqGeometry.LEGS];
    private final double[] leg = new double[12];
    private final double[] foot = new double[3];
    private final double[] feetInWorld = new double[2 * RoqGeometry.LEGS];
    private final double[] headingValue = new double[1];
    private double heading;
    private String positionText;
    private String attitudeText;
    private String anglesText;
    private String forcesText;
    private String headingText;
    private long lastCheck;
    private boolean anyCheck;
    private long lastFrame;
    private boolean anyFrame;
    private boolean courseSent;

    RoqScene(RoqNodes nodes, List<FragileCell> cells) {
        this.nodes = nodes;
        this.cells = cells;
        this.broken = new boolean[cells.size()];
        this.pressedSince = new long[cells.size()];
        java.util.Arrays.fill(pressedSince, -1);
    }

    @Override
    public List<Topic> topics() {
        return List.of(new Topic("/roq/tf", FoxgloveJson.FRAME_TRANSFORM, FoxgloveJson.frameTransformSchema()),
                new Topic("/roq/robot", FoxgloveJson.SCENE_UPDATE, FoxgloveJson.sceneUpdateSchema()),
                new Topic("/roq/course", FoxgloveJson.SCENE_UPDATE, FoxgloveJson.sceneUpdateSchema()));
    }

    @Override
    public void accept(ExportRow row, Out out) throws IOException {
        if (row.kind() != ExportRow.Kind.DATA || row.value() == null) {
            return;
        }
        int id = row.sourceId();
        long nanos = row.time() * 1000;
        if (!courseSent && !cells.isEmpty()) {
            courseSent = true;
            out.emit(2, nanos, course(nanos));
        }
        // the texts are kept and parsed only when drawn or checked: most rows are never looked at again
        if (id == nodes.position()) {
            positionText = row.value();
        } else if (id == nodes.attitude()) {
            attitudeText = row.value();
        } else if (id == nodes.heading()) {
            headingText = row.value();
        } else if (id == nodes.angles()) {
            anglesText = row.value();
        } else if (id == nodes.forces()) {
            forcesText = row.value();
        } else {
            return;
        }
        if (positionText == null || anglesText == null) {
            return;
        }
        if (!cells.isEmpty() && forcesText != null && (!anyCheck || nanos - lastCheck >= CHECK_NANOS)) {
            anyCheck = true;
            lastCheck = nanos;
            if (parse() && pressCells(row.time())) {
                out.emit(2, nanos, course(nanos));
            }
        }
        if (!anyFrame || nanos - lastFrame >= FRAME_NANOS) {
            anyFrame = true;
            lastFrame = nanos;
            if (parse()) {
                double[] q = FoxgloveJson.rotation(attitude[0], attitude[1], heading);
                out.emit(0, nanos, FoxgloveJson.frameTransform(nanos, "world", "body", position[0], position[1], position[2], q));
                out.emit(1, nanos, robot(nanos));
            }
        }
    }

    /** Parses the latest texts; false when position or angles are not (yet) numbers of their length. */
    private boolean parse() {
        boolean ok = read(positionText, position) && read(anglesText, angles);
        if (attitudeText != null) {
            read(attitudeText, attitude);
        }
        if (forcesText != null) {
            read(forcesText, forces);
        }
        if (headingText != null && read(headingText, headingValue)) {
            heading = headingValue[0];
        }
        return ok;
    }

    private String robot(long nanos) {
        StringBuilder lines = new StringBuilder();
        StringBuilder spheres = new StringBuilder();
        StringBuilder arrows = new StringBuilder();
        for (int l = 0; l < RoqGeometry.LEGS; l++) {
            RoqGeometry.legInBody(l, angles[3 * l], angles[3 * l + 1], angles[3 * l + 2], leg);
            String sep = l > 0 ? "," : "";
            lines.append(sep).append(FoxgloveJson.lineStrip(leg, 0.025, FoxgloveJson.color(0x20262E, 1)));
            boolean contact = forces[l] > CONTACT_NEWTONS;
            String foot = FoxgloveJson.pose(leg[9], leg[10], leg[11], FoxgloveJson.IDENTITY);
            spheres.append(sep).append(FoxgloveJson.sphere(foot, 2 * RoqGeometry.FOOT_RADIUS,
                    FoxgloveJson.color(contact ? 0x2E9E44 : 0xC8C8C8, 1)));
            if (contact) {
                arrows.append(arrows.length() > 0 ? "," : "").append(FoxgloveJson.arrow(
                        FoxgloveJson.pose(leg[9], leg[10], leg[11] - RoqGeometry.FOOT_RADIUS, ARROW_UP),
                        forces[l] * ARROW_METRES_PER_NEWTON, FoxgloveJson.color(0xC0392B, 0.9)));
            }
        }
        String body = FoxgloveJson.cube(FoxgloveJson.pose(0, 0, 0, FoxgloveJson.IDENTITY), RoqGeometry.BODY_LENGTH,
                RoqGeometry.BODY_WIDTH, RoqGeometry.BODY_HEIGHT, FoxgloveJson.color(0x3B5B92, 1));
        return FoxgloveJson.sceneUpdate(FoxgloveJson.entity(nanos, "body", "roq", arrows.toString(), body,
                spheres.toString(), lines.toString()));
    }

    private String course(long nanos) {
        StringBuilder cubes = new StringBuilder();
        for (int i = 0; i < cells.size(); i++) {
            FragileCell c = cells.get(i);
            double height = broken[i] ? 0.01 : c.height();
            cubes.append(i > 0 ? "," : "").append(FoxgloveJson.cube(
                    FoxgloveJson.pose(c.x(), c.y(), height / 2, FoxgloveJson.IDENTITY), c.sizeX(), c.sizeY(), height,
                    FoxgloveJson.color(broken[i] ? 0x5A2A0A : 0xE39B2D, broken[i] ? 1 : 0.8)));
        }
        return FoxgloveJson.sceneUpdate(FoxgloveJson.entity(nanos, "world", "fragile cells", "", cubes.toString(), "", ""));
    }

    /** Applies the break rule to the feet now; true when a cell broke. */
    private boolean pressCells(long micros) {
        if (cells.isEmpty()) {
            return false;
        }
        double cos = Math.cos(heading);
        double sin = Math.sin(heading);
        for (int l = 0; l < RoqGeometry.LEGS; l++) {
            RoqGeometry.footInBody(l, angles[3 * l], angles[3 * l + 1], angles[3 * l + 2], foot);
            feetInWorld[2 * l] = position[0] + cos * foot[0] - sin * foot[1];
            feetInWorld[2 * l + 1] = position[1] + sin * foot[0] + cos * foot[1];
        }
        boolean changed = false;
        for (int i = 0; i < cells.size(); i++) {
            if (broken[i]) {
                continue;
            }
            FragileCell c = cells.get(i);
            boolean pressed = false;
            for (int l = 0; l < RoqGeometry.LEGS && !pressed; l++) {
                pressed = forces[l] > c.strength() && c.contains(feetInWorld[2 * l], feetInWorld[2 * l + 1]);
            }
            if (!pressed) {
                pressedSince[i] = -1;
            } else if (pressedSince[i] < 0) {
                pressedSince[i] = micros;
            } else if (micros - pressedSince[i] >= FragileCell.BREAK_HOLD_SECONDS * 1e6) {
                broken[i] = true;
                changed = true;
            }
        }
        return changed;
    }

    /** Reads the stored text of a vector (or a number) into {@code into}; false when it is shorter or not numbers. */
    private static boolean read(String text, double[] into) {
        String[] parts = text.split(",");
        if (parts.length < into.length) {
            return false;
        }
        try {
            for (int i = 0; i < into.length; i++) {
                into[i] = Double.parseDouble(parts[i]);
            }
            return true;
        } catch (NumberFormatException e) {
            return false;
        }
    }
}

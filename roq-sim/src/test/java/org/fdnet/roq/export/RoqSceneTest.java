package org.fdnet.roq.export;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import org.fdnet.event.ValueType;
import org.fdnet.logger.export.ExportRow;
import org.fdnet.logger.export.RecordedNode;
import org.fdnet.logger.export.RecordedRun;
import org.fdnet.logger.export.RunScene;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.sim.FragileCell;
import org.fdnet.roq.sim.RoqGeometry;
import org.junit.jupiter.api.Test;

class RoqSceneTest {
    private static final int POSITION = 1;
    private static final int ANGLES = 2;
    private static final int FORCES = 3;
    private static final long START = 1_795_000_000_000_000L;

    private record Emitted(int topic, long nanos, String json) {
    }

    @Test
    void shouldOfferNoSceneForARunWithoutRoqsDatas() {
        RecordedRun other = run(Map.of(7, new RecordedNode(7, NodeKind.DATA, "main", "pitch", "h", 0)));
        assertThat(new RoqSceneSource().sceneOf(other, Map.of())).isEmpty();
    }

    @Test
    void shouldDrawTheBodyAndItsFourLegsThirtyTimesASecondOfRecordedTime() throws Exception {
        RunScene scene = new RoqSceneSource().sceneOf(roqRun(), Map.of()).orElseThrow();
        List<Emitted> out = feed(scene, 0, 0, 20, 1000); // 1 s at 1 kHz, light soles
        long frames = out.stream().filter(e -> e.topic == 0).count();
        assertThat(frames).isBetween(29L, 31L);
        List<Emitted> robots = out.stream().filter(e -> e.topic == 1).toList();
        Emitted robot = robots.get(robots.size() - 1); // the first came before any sole force
        assertThat(robot.json).contains("\"frame_id\":\"body\"").contains("\"spheres\":[{").contains("\"arrows\":[{");
        assertThat(robot.json.split("\"type\":0").length - 1).isEqualTo(RoqGeometry.LEGS);
        assertThat(out.stream().filter(e -> e.topic == 2)).isEmpty(); // no course given
    }

    @Test
    void shouldBreakACellWhereARecordedFootPressedBeyondItsStrengthForItsHold() throws Exception {
        FragileCell cell = CourseLoader.resolve("crossing").fragileCells().get(0);
        double[] foot = RoqGeometry.footInBody(0, RoqGeometry.STANDING_POSE[0], RoqGeometry.STANDING_POSE[1],
                RoqGeometry.STANDING_POSE[2], new double[3]);
        RunScene pressed = new RoqSceneSource().sceneOf(roqRun(), Map.of("course", "crossing")).orElseThrow();
        List<Emitted> out = feed(pressed, cell.x() - foot[0], cell.y() - foot[1], cell.strength() + 10, 300);
        List<Emitted> course = out.stream().filter(e -> e.topic == 2).toList();
        assertThat(course).hasSize(2); // the cells, then the first one broken
        assertThat(course.get(1).nanos - course.get(0).nanos).isBetween(100_000_000L, 120_000_000L);

        RunScene light = new RoqSceneSource().sceneOf(roqRun(), Map.of("course", "crossing")).orElseThrow();
        assertThat(feed(light, cell.x() - foot[0], cell.y() - foot[1], cell.strength() - 10, 300).stream()
                .filter(e -> e.topic == 2)).hasSize(1);
    }

    /** {@code millis} ms of RoQ standing at (x, y), the front-left sole bearing {@code force} N, at 1 kHz. */
    private static List<Emitted> feed(RunScene scene, double x, double y, double force, int millis) throws Exception {
        List<Emitted> out = new ArrayList<>();
        RunScene.Out sink = (topic, nanos, json) -> out.add(new Emitted(topic, nanos, json));
        StringBuilder angles = new StringBuilder();
        for (int l = 0; l < RoqGeometry.LEGS; l++) {
            for (double a : RoqGeometry.STANDING_POSE) {
                angles.append(angles.length() > 0 ? "," : "").append(a);
            }
        }
        ExportRow row = new ExportRow();
        for (int ms = 0; ms < millis; ms++) {
            long t = START + ms * 1000L;
            scene.accept(row.data(POSITION, t, ValueType.DOUBLES, x + "," + y + ",0.3"), sink);
            scene.accept(row.data(ANGLES, t, ValueType.DOUBLES, angles.toString()), sink);
            scene.accept(row.data(FORCES, t, ValueType.DOUBLES, force + ",40,40,40"), sink);
        }
        return out;
    }

    private static RecordedRun roqRun() {
        Map<Integer, RecordedNode> nodes = new LinkedHashMap<>();
        nodes.put(POSITION, new RecordedNode(POSITION, NodeKind.DATA, "main", "body position", "robot", 0));
        nodes.put(ANGLES, new RecordedNode(ANGLES, NodeKind.DATA, "main", "joint angles", "robot", 0));
        nodes.put(FORCES, new RecordedNode(FORCES, NodeKind.DATA, "main", "foot forces", "robot", 0));
        return run(nodes);
    }

    private static RecordedRun run(Map<Integer, RecordedNode> nodes) {
        return new RecordedRun(1, "roq", "", START, List.of("robot"), null, null, List.of(1), nodes);
    }
}

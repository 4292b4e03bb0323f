package org.fdnet.roq.sim;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.data.Offset.offset;

import java.util.List;
import org.junit.jupiter.api.Test;

/** RoqGeometry and the model MuJoCo loaded agree: they cannot drift apart. */
class RoqGeometryTest {
    @Test
    void shouldMatchTheLoadedModelsMassesAndJoints() {
        try (RoqSimulator sim = RoqSimulator.open(Course.flat(), SimMode.STEPPED)) {
            assertThat(sim.modelValue(3, "")).isCloseTo(RoqGeometry.TOTAL_MASS, offset(1e-9));
            assertThat(sim.modelValue(0, "body")).isCloseTo(RoqGeometry.BODY_MASS, offset(1e-9));
            for (int leg = 0; leg < RoqGeometry.LEGS; leg++) {
                String n = RoqGeometry.LEG_NAMES[leg];
                assertThat(sim.modelValue(0, n + "_coxa")).isCloseTo(RoqGeometry.COXA_MASS, offset(1e-9));
                assertThat(sim.modelValue(0, n + "_thigh")).isCloseTo(RoqGeometry.THIGH_MASS, offset(1e-9));
                assertThat(sim.modelValue(0, n + "_shank")).isCloseTo(RoqGeometry.SHANK_MASS, offset(1e-9));
                assertThat(sim.modelValue(0, n + "_wheel")).isCloseTo(RoqGeometry.FOOT_MASS, offset(1e-9));
            }
            for (int j = 0; j < RoqGeometry.JOINTS; j++) {
                String name = RoqGeometry.jointName(j);
                assertThat(sim.modelValue(1, name)).as(name).isCloseTo(RoqGeometry.jointMin(j), offset(1e-12));
                assertThat(sim.modelValue(2, name)).as(name).isCloseTo(RoqGeometry.jointMax(j), offset(1e-12));
                assertThat(sim.modelValue(7, name)).as(name).isCloseTo(RoqGeometry.armature(), offset(1e-12));
                assertThat(sim.modelValue(8, name)).as(name).isCloseTo(RoqGeometry.JOINT_FRICTION, offset(1e-12));
                assertThat(sim.modelValue(9, name)).as(name).isCloseTo(RoqGeometry.JOINT_DAMPING, offset(1e-12));
            }
            assertThat(sim.modelValue(0, "no_such_body")).isNaN();
        }
    }

    @Test
    void shouldPlaceEachFootWhereTheForwardKinematicsSays() {
        Course course = Course.flat().withStart(0.3, -0.2);
        try (RoqSimulator sim = RoqSimulator.open(course, SimMode.STEPPED)) {
            SensorSnapshot s = new SensorSnapshot();
            sim.read(s);
            double[] foot = new double[3];
            for (int leg = 0; leg < RoqGeometry.LEGS; leg++) {
                RoqGeometry.footInBody(leg, s.jointAngle(3 * leg), s.jointAngle(3 * leg + 1), s.jointAngle(3 * leg + 2), foot);
                String geom = RoqGeometry.footName(leg);
                assertThat(sim.modelValue(4, geom)).as(geom + " x").isCloseTo(s.groundTruthBodyPosition(0) + foot[0], offset(1e-9));
                assertThat(sim.modelValue(5, geom)).as(geom + " y").isCloseTo(s.groundTruthBodyPosition(1) + foot[1], offset(1e-9));
                assertThat(sim.modelValue(6, geom)).as(geom + " z").isCloseTo(s.groundTruthBodyPosition(2) + foot[2], offset(1e-9));
                assertThat(sim.modelValue(6, geom)).as(geom + " rests on the ground").isCloseTo(RoqGeometry.FOOT_RADIUS, offset(0.002));
            }
        }
    }

    @Test
    void shouldBuildTheTerrainMuJoCoSeesFromTheHeightfield() throws Exception {
        Course course = CourseLoader.resolve("rubble").withFragileCells(List.of(new FragileCell(0.6, -0.35, 0.2, 0.2, 0.04, 50)));
        try (RoqSimulator sim = RoqSimulator.open(course, SimMode.STEPPED)) {
            Heightfield h = sim.heightfield();
            for (int r = 1; r < h.rows() - 1; r += 3) {
                for (int c = 1; c < h.cols() - 1; c += 7) {
                    if (course.fragileCells().get(0).contains(h.x(c), h.y(r))) {
                        continue;
                    }
                    double probed = sim.modelValue(10, h.x(c) + " " + h.y(r));
                    assertThat(probed).as("ground at row %d col %d", r, c).isCloseTo(h.height(r, c), offset(1e-4));
                }
            }
            assertThat(sim.modelValue(10, "0.6 -0.35")).as("the cell's top is flush with its terrain")
                    .isCloseTo(h.cellTop(0), offset(1e-6));
        }
    }
}

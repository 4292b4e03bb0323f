package org.fdnet.roq.testkit.scratch;

import java.nio.file.Path;
import java.time.Duration;
import org.fdnet.roq.testkit.SimulatedRoq;
import org.junit.jupiter.api.Test;

class ScratchTransferTest {
    @Test
    void run() {
        String net = System.getProperty("net", "roq-transfer");
        String course = System.getProperty("course", "crossing");
        int secs = Integer.getInteger("secs", 60);
        System.setProperty("gait.times", System.getProperty("gtimes", "false"));
        System.setProperty("gait.acc", System.getProperty("gacc", "0.6"));
        System.setProperty("gait.debug", System.getProperty("gdebug", "false"));
        for (String seed : System.getProperty("seeds", "1").split(",")) {
            try (SimulatedRoq roq = SimulatedRoq.builder().network(Path.of("../../networks/" + net + ".fdn"))
                    .course(course).noise(Long.parseLong(seed)).start()) {
                long t0 = System.nanoTime();
                int[] seen = {0, 0};
                double[][] anchor = new double[4][];
                double[] worst = new double[4];
                int[] slides = new int[1];
                java.util.Map<String, Integer> byPhase = new java.util.TreeMap<>();
                roq.afterEachStep(r -> {
                    var snap = r.snapshot();
                    double[] foot = new double[3];
                    double[] world = new double[3];
                    for (int leg = 0; leg < 4; leg++) {
                        org.fdnet.roq.sim.RoqGeometry.footInBody(leg, snap.jointAngle(3 * leg), snap.jointAngle(3 * leg + 1),
                                snap.jointAngle(3 * leg + 2), foot);
                        snap.groundTruthToWorld(foot, world);
                        if (snap.footForce(leg) > 20) {
                            if (anchor[leg] == null) {
                                anchor[leg] = new double[] {world[0], world[1]};
                                worst[leg] = 0;
                            }
                            double d = Math.hypot(world[0] - anchor[leg][0], world[1] - anchor[leg][1]);
                            if (d > 0.02 && worst[leg] <= 0.02) {
                                slides[0]++;
                                var ph = r.network().value("gait phase");
                                String k = ph == null ? "?" : (int) ph.element(0) + "/" + (int) ph.element(1) + "/" + (int) ph.element(3) + " leg " + leg;
                                byPhase.merge(k, 1, Integer::sum);
                            }
                            worst[leg] = Math.max(worst[leg], d);
                        } else if (snap.footForce(leg) < 5) {
                            anchor[leg] = null;
                        }
                    }
                });
                roq.afterEachStep(r -> {
                    var m = r.measures();
                    if (m.loadedBreakthroughs() != seen[0] || m.probeBroken() != seen[1]) {
                        seen[0] = m.loadedBreakthroughs();
                        seen[1] = m.probeBroken();
                        System.out.println("BREAK at " + r.time() + " loaded " + seen[0] + " probe " + seen[1] + " | "
                                + status(r));
                    }
                });
                for (int s = 0; s < secs; s++) {
                    roq.runFor(Duration.ofSeconds(1));
                    if (Boolean.getBoolean("trace") || s % 10 == 9) {
                        System.out.println("t=" + (s + 1) + " " + roq.measures() + " | " + status(roq));
                    }
                }
                System.out.printf("SEED %s: %s (%.1f s wall)%n", seed, roq.measures(), (System.nanoTime() - t0) / 1e9);
 System.out.println("  TRUE SLIDES " + slides[0] + " " + byPhase);
                System.out.println("  slack " + val(roq, "slack ticks", "Forces") + " slips " + val(roq, "slips", "Gait")
                        + " rejected " + val(roq, "footholds rejected", "Gait"));
            }
        }
    }

    private static String status(SimulatedRoq roq) {
        try {
            return roq.network().value("gait phase") + " targets "
                    + roq.network().value("Forces" + "/" + "sole targets") + " forces "
                    + roq.network().value("foot forces");
        } catch (RuntimeException e) {
            return e.toString();
        }
    }

    private static Object val(SimulatedRoq roq, String name, String module) {
        try {
            return roq.network().value(module + "/" + name);
        } catch (RuntimeException e) {
            return "-";
        }
    }
}

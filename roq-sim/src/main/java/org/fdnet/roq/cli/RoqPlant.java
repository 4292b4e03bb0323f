package org.fdnet.roq.cli;

import java.io.PrintWriter;
import java.util.Locale;
import org.fdnet.roq.bridge.SimBridge;
import org.fdnet.roq.sim.Course;
import org.fdnet.roq.sim.CourseFormatException;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.sim.LoopStatistics;
import org.fdnet.roq.sim.RoqSimulator;
import org.fdnet.roq.sim.SensorSnapshot;
import org.fdnet.roq.sim.SimMode;
import org.fdnet.runtime.cli.SimulatedPlant;
import org.fdnet.runtime.engine.RuntimeNetwork;

/**
 * RoQ's simulator for {@code fdnet run FILE --sim COURSE}: the real-time simulator joined to the running network
 * by the real-time {@link SimBridge}. Listed in {@code META-INF/services/org.fdnet.runtime.cli.SimulatedPlant}.
 */
public final class RoqPlant implements SimulatedPlant {
    @Override
    public Run attach(RuntimeNetwork network, String course, PrintWriter out) {
        Course c;
        try {
            c = CourseLoader.resolve(course);
        } catch (CourseFormatException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        }
        RoqSimulator sim = RoqSimulator.open(c, SimMode.REAL_TIME);
        SimBridge bridge;
        try {
            bridge = SimBridge.realTime(network, sim);
        } catch (RuntimeException e) {
            sim.close();
            throw e;
        }
        SensorSnapshot s = new SensorSnapshot();
        sim.read(s);
        double startX = s.groundTruthBodyPosition(0);
        out.printf(Locale.ROOT, "simulated RoQ on course %s, real time, joined by the bridge%n", c.name());
        out.flush();
        return new Run() {
            @Override
            public String status() {
                sim.read(s);
                return String.format(Locale.ROOT, "sim t=%.1f s  distance %.3f m  height %.3f m  broken cells %d"
                                + "  bridge cycles %,d", s.simTime(), s.groundTruthBodyPosition(0) - startX,
                        s.groundTruthBodyPosition(2), s.brokenCellCount(), bridge.cycles());
            }

            @Override
            public String summary() {
                LoopStatistics st = sim.statistics(new LoopStatistics());
                sim.read(s);
                return String.format(Locale.ROOT, "simulated RoQ: %.3f m forward in %.1f s, broken cells %d; loop %,d"
                                + " ticks, %,d overruns, wake-up p99 %.1f µs, %,d commands applied, reflex p99 %d ms",
                        s.groundTruthBodyPosition(0) - startX, s.simTime(), s.brokenCellCount(), st.ticks(),
                        st.overruns(), st.latencyPercentileNanos(99) / 1e3, st.commandsApplied(),
                        st.reflexPercentileTicks(99));
            }

            @Override
            public void close() {
                bridge.close();
                sim.close();
            }
        };
    }
}

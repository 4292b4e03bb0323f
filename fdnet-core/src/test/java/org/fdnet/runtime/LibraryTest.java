package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.within;
import static org.fdnet.runtime.TestNetworks.*;

import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** Each library Relation in a tiny network: In → Relation → Out (more inputs where it needs them). */
@Timeout(30)
class LibraryTest {

    private static NetworkInfo oneInOneOut(String cls, String inClass, String outClass, String... params) {
        NetworkInfo n = new NetworkInfo(cls);
        n.addNode("main", data("In", inClass));
        n.addNode("main", data("Out", outClass));
        n.addNode("main", relation("R", cls, params));
        read(n, "main", "In", "R");
        write(n, "main", "R", "Out");
        return n;
    }

    private static double feed(RuntimeNetwork net, double... values) throws InterruptedException {
        for (double v : values) {
            net.controller().setValue(ref("In"), Value.of(v));
            quiet(net);
        }
        return net.controller().value(ref("Out")).asDouble();
    }

    @Test
    void expressionShouldComputeWithPrecedenceFunctionsAndVectors() throws Exception {
        try (RuntimeNetwork net = start(oneInOneOut("Expression", "DoubleData", "DoubleData",
                "expression=1 + 2 * in0 ^ 2 - max(in0, 10) / 5 + (in0 > 2 ? 100 : 0)"), null)) {
            assertThat(feed(net, 3)).isEqualTo(1 + 18 - 2 + 100);
        }
        try (RuntimeNetwork net = start(oneInOneOut("Expression", "DoubleData", "DoublesData",
                "expression=in0 * [1, -1, 2] + mean([2, 4])"), null)) {
            net.controller().setValue(ref("In"), "2");
            quiet(net);
            assertThat(net.controller().value(ref("Out")).asDoubles()).containsExactly(5, 1, 7);
        }
    }

    @Test
    void movingAverageShouldAverageTheLastWindow() throws Exception {
        try (RuntimeNetwork net = start(oneInOneOut("MovingAverage", "DoubleData", "DoubleData", "window=3"), null)) {
            // the initial 0 is the first value of the window
            assertThat(feed(net, 3, 6, 9, 12)).isEqualTo(9.0);
        }
    }

    @Test
    void lowPassShouldMoveAlphaOfTheWay() throws Exception {
        try (RuntimeNetwork net = start(oneInOneOut("LowPass", "DoubleData", "DoubleData", "alpha=0.25"), null)) {
            assertThat(feed(net, 8)).isEqualTo(2.0);
            assertThat(feed(net, 8)).isEqualTo(3.5);
        }
    }

    @Test
    void thresholdShouldSwitchWithHysteresis() throws Exception {
        try (RuntimeNetwork net = start(oneInOneOut("Threshold", "DoubleData", "BooleanData", "high=10", "low=5"), null)) {
            feed(net, 11);
            assertThat(net.controller().value(ref("Out")).asBoolean()).isTrue();
            feed(net, 7);
            assertThat(net.controller().value(ref("Out")).asBoolean()).isTrue();
            feed(net, 4);
            assertThat(net.controller().value(ref("Out")).asBoolean()).isFalse();
            feed(net, 9);
            assertThat(net.controller().value(ref("Out")).asBoolean()).isFalse();
        }
    }

    @Test
    void rateLimiterShouldNotMoveFasterThanMaxRate() throws Exception {
        try (RuntimeNetwork net = start(oneInOneOut("RateLimiter", "DoubleData", "DoubleData", "maxRate=10", "period=5"), null)) {
            net.controller().setValue(ref("In"), "100");
            Thread.sleep(200);
            double out = net.controller().value(ref("Out")).asDouble();
            assertThat(out).isBetween(0.5, 4.0);
        }
    }

    @Test
    void pdControllerShouldPushTowardTheSetPoint() throws Exception {
        try (RuntimeNetwork net = start(oneInOneOut("PdController", "DoubleData", "DoubleData", "kp=2", "setpoint=5",
                "limit=6"), null)) {
            assertThat(feed(net, 3)).isEqualTo(4.0);
            assertThat(feed(net, 0)).isEqualTo(6.0);
        }
    }

    @Test
    void constantShouldWriteItsValueAtStart() throws Exception {
        NetworkInfo n = new NetworkInfo("constant");
        n.addNode("main", data("Pose", "DoublesData"));
        n.addNode("main", relation("Home", "Constant", "value=0.3 0.3 0.2"));
        write(n, "main", "Home", "Pose");
        try (RuntimeNetwork net = start(n, null)) {
            quiet(net);
            assertThat(net.controller().value(ref("Pose")).asDoubles()).containsExactly(0.3, 0.3, 0.2);
        }
    }

    @Test
    void selectorShouldPassTheChosenInput() throws Exception {
        NetworkInfo n = new NetworkInfo("selector");
        n.addNode("main", data("Which", "LongData"));
        n.addNode("main", data("A", "DoubleData", "initial=10"));
        n.addNode("main", data("B", "DoubleData", "initial=20"));
        n.addNode("main", data("Out", "DoubleData"));
        n.addNode("main", relation("Pick", "Selector", "select=Which"));
        read(n, "main", "Which", "Pick");
        read(n, "main", "A", "Pick");
        read(n, "main", "B", "Pick");
        write(n, "main", "Pick", "Out");
        try (RuntimeNetwork net = start(n, null)) {
            net.controller().setValue(ref("Which"), "1");
            quiet(net);
            assertThat(net.controller().value(ref("Out")).asDouble()).isEqualTo(20.0);
            net.controller().setValue(ref("Which"), "0");
            quiet(net);
            assertThat(net.controller().value(ref("Out")).asDouble()).isEqualTo(10.0);
        }
    }

    @Test
    void integrationShouldWeighCandidatesByTheJudgment() throws Exception {
        NetworkInfo n = new NetworkInfo("integration");
        n.addNode("main", data("Balance", "DoublesData", "initial=0 0"));
        n.addNode("main", data("Walk", "DoublesData", "initial=10 20"));
        n.addNode("main", data("Judgment", "DoubleData"));
        n.addNode("main", data("Posture", "DoublesData", "initial=0 0"));
        n.addNode("main", relation("Integrate", "Integration", "judgment=Judgment", "present=Posture",
                "weights=1 0", "movingWeights=0.5 0.5", "gain=1"));
        read(n, "main", "Balance", "Integrate");
        read(n, "main", "Walk", "Integrate");
        read(n, "main", "Judgment", "Integrate");
        read(n, "main", "Posture", "Integrate");
        write(n, "main", "Integrate", "Posture");
        try (RuntimeNetwork net = start(n, null)) {
            quiet(net);
            assertThat(net.controller().value(ref("Posture")).asDoubles()).containsExactly(0, 0);
            net.controller().setValue(ref("Judgment"), "1");
            quiet(net);
            assertThat(net.controller().value(ref("Posture")).asDoubles()).containsExactly(5, 10);
            // "move, but just a little": judgment 0.5 weighs balance 0.75, walk 0.25
            net.controller().setValue(ref("Judgment"), "0.5");
            quiet(net);
            double[] p = net.controller().value(ref("Posture")).asDoubles();
            assertThat(p[0]).isCloseTo(2.5, within(1e-9));
            assertThat(p[1]).isCloseTo(5.0, within(1e-9));
        }
    }

    @Test
    void printShouldPrintItsInputs() throws Exception {
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        java.io.PrintStream old = System.out;
        System.setOut(new java.io.PrintStream(bytes, true));
        try {
            NetworkInfo n = new NetworkInfo("print");
            n.addNode("main", data("Speed", "DoubleData", "initial=1.5"));
            n.addNode("main", relation("Show", "Print", "prefix=speedo"));
            read(n, "main", "Speed", "Show");
            try (RuntimeNetwork net = start(n, null)) {
                quiet(net);
            }
        } finally {
            System.setOut(old);
        }
        assertThat(bytes.toString()).contains("[speedo]").contains("main/Speed=1.5000");
    }
}

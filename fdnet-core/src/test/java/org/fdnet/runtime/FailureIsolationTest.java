package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.fdnet.runtime.TestNetworks.*;

import org.fdnet.event.MemoryEventSink;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class FailureIsolationTest {

    /** Divides 1 by its input with integer arithmetic: input 0 throws. Parameter {@code offset} shifts it. */
    public static class Reciprocal extends Relation {
        long offset;

        @Override
        protected void init(NodeParameters p) {
            offset = p.longValue("offset", 0);
        }

        @Override
        protected void compute(RelationContext c) {
            c.outputAll(Value.of(100 / (c.input(0).asLong() + offset)));
        }
    }

    private static NetworkInfo network() {
        NetworkInfo n = new NetworkInfo("fragile");
        n.addNode("main", data("In", "LongData", "initial=1"));
        n.addNode("main", data("Out", "LongData"));
        n.addNode("main", data("Copy", "LongData"));
        n.addNode("main", relation("Divide", Reciprocal.class.getName()));
        n.addNode("main", relation("Mirror", "Expression", "expression=in0"));
        read(n, "main", "In", "Divide");
        write(n, "main", "Divide", "Out");
        read(n, "main", "In", "Mirror");
        write(n, "main", "Mirror", "Copy");
        return n;
    }

    @Test
    void shouldMarkAThrowingRelationFailedWithItsCauseAndRunTheRestOn() throws Exception {
        MemoryEventSink sink = new MemoryEventSink();
        try (RuntimeNetwork net = start(network(), sink)) {
            quiet(net);
            net.controller().setValue(ref("In"), "0");
            quiet(net);
            RelationState state = net.controller().relationState(ref("Divide"));
            assertThat(state.status()).isEqualTo(RelationStatus.FAILED);
            assertThat(state.cause()).isInstanceOf(ArithmeticException.class);
            int id = net.controller().nodeId(ref("Divide"));
            assertThat(sink.events(RelationValueEvent.class)).anySatisfy(e -> {
                assertThat(e.sourceId()).isEqualTo(id);
                assertThat(e.value()).startsWith("FAILED: java.lang.ArithmeticException");
            });
            // the failed firing wrote nothing; the rest runs on
            assertThat(net.controller().value(ref("Out")).asLong()).isEqualTo(100);
            net.controller().setValue(ref("In"), "5");
            quiet(net);
            assertThat(net.controller().value(ref("Copy")).asLong()).isEqualTo(5);
            assertThat(net.controller().value(ref("Out")).asLong()).isEqualTo(100);
        }
    }

    @Test
    void shouldRestartAFailedRelationWhenAParameterChanges() throws Exception {
        try (RuntimeNetwork net = start(network(), null)) {
            net.controller().setValue(ref("In"), "0");
            quiet(net);
            assertThat(net.controller().relationState(ref("Divide")).status()).isEqualTo(RelationStatus.FAILED);
            ChangeOutcome outcome = net.controller().setParameter(ref("Divide"), "offset", "4");
            assertThat(outcome.executed()).isTrue();
            quiet(net);
            assertThat(net.controller().relationState(ref("Divide")).status()).isEqualTo(RelationStatus.RUNNING);
            assertThat(net.controller().value(ref("Out")).asLong()).isEqualTo(25);
        }
    }

    @Test
    void shouldRestartAFailedRelationOnRequest() throws Exception {
        try (RuntimeNetwork net = start(network(), null)) {
            net.controller().setValue(ref("In"), "0");
            quiet(net);
            net.controller().setValue(ref("In"), "2");
            quiet(net);
            assertThat(net.controller().relationState(ref("Divide")).status()).isEqualTo(RelationStatus.FAILED);
            assertThat(net.controller().restart(ref("Divide")).executed()).isTrue();
            quiet(net);
            assertThat(net.controller().value(ref("Out")).asLong()).isEqualTo(50);
        }
    }

    @Test
    void shouldFailAWriterWhoseValueDoesNotFitItsData() throws Exception {
        NetworkInfo n = new NetworkInfo("misfit");
        n.addNode("main", data("In", "DoubleData"));
        n.addNode("main", data("Posture", "DoublesData", "length=2"));
        n.addNode("main", relation("Bad", "Expression", "expression=[in0, in0, in0]"));
        read(n, "main", "In", "Bad");
        write(n, "main", "Bad", "Posture");
        try (RuntimeNetwork net = start(n, null)) {
            quiet(net);
            RelationState s = net.controller().relationState(ref("Bad"));
            assertThat(s.status()).isEqualTo(RelationStatus.FAILED);
            assertThat(s.cause()).hasMessageContaining("writing main/Posture");
            assertThat(net.controller().value(ref("Posture")).asDoubles()).containsExactly(0, 0);
        }
    }
}

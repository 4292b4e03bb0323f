package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.fdnet.runtime.TestNetworks.*;

import java.nio.file.Path;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.event.RelationValueEvent;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** networks/servant-messages.fdn on one host: Driver asks Planner's servant, which knows Obstacle, through messages. */
@Timeout(30)
class ServantMessagesTest {

    private static NetworkInfo example() throws Exception {
        return NetworkRepository.load(Path.of("../networks/servant-messages.fdn"));
    }

    @Test
    void shouldWriteTheServantsReplyToEachWishIntoSpeed() throws Exception {
        try (RuntimeNetwork net = start(example(), null)) {
            Controller c = net.controller();
            // Throttle keeps changing Wish; the replies are min(Wish, 0.5 * Obstacle) with Obstacle = 4
            eventually("a capped speed", () -> c.value(ref("Speed")) != null && c.value(ref("Speed")).asDouble() == 2.0);
            c.setValue(ref("Obstacle"), "10");
            eventually("a speed above the old cap", () -> c.value(ref("Speed")).asDouble() > 2.0);
            assertThat(c.value(ref("Speed")).asDouble()).isLessThanOrEqualTo(6.0);
        }
    }

    @Test
    void shouldRefuseMessagesOnceTheServingRelationLeavesTheNetwork() throws Exception {
        try (RuntimeNetwork net = start(example(), null)) {
            eventually("the servant offered", () -> net.servantRegistry().find("planner/speed") != null);
            assertThat(ask(net, "speed", 9.0).asDouble()).isEqualTo(2.0);
            assertThat(net.controller().apply("destroy Planner",
                    d -> d.deleteNode(ref("Planner"))).executed()).isTrue();
            eventually("the servant withdrawn", () -> net.servantRegistry().find("planner/speed") == null);
            CompletableFuture<String> refusal = new CompletableFuture<>();
            net.servantRegistry().sendMessage("planner/speed", "speed", Value.of(1.0),
                    ReturnListener.of(v -> refusal.complete("answered " + v), refusal::complete));
            assertThat(refusal.get(10, TimeUnit.SECONDS)).isEqualTo("no servant at planner/speed in this network");
        }
    }

    /** Offers "forgetful" and never withdraws it: the engine still takes the servant away with the Relation. */
    public static final class ForgetfulServant extends Relation {
        private boolean offered;

        @Override
        protected void compute(RelationContext context) {
            if (!offered) {
                context.servants().offer("forgetful", (message, argument) -> Value.of(argument.asDouble() + 1));
                offered = true;
            }
        }
    }

    @Test
    void shouldTakeAServantAwayWithItsRelationEvenWhenTheRelationForgets() throws Exception {
        NetworkInfo n = new NetworkInfo("forgetful");
        n.addModule("Extra", true);
        n.addNode("Extra", relation("Forgetful", ForgetfulServant.class.getName()));
        try (RuntimeNetwork net = start(n, null)) {
            eventually("the servant offered", () -> net.servantRegistry().find("forgetful") != null);
            assertThat(net.controller().unload("Extra").executed()).isTrue();
            assertThat(net.servantRegistry().find("forgetful")).isNull();
            assertThat(net.controller().load("Extra").executed()).isTrue();
            eventually("the new instance's servant offered at the same path",
                    () -> net.servantRegistry().find("forgetful") != null);
        }
    }

    @Test
    void shouldReportARefusedMessageAsTheAskersStatus() throws Exception {
        NetworkInfo n = NetworkRepository.fromText(NetworkRepository.toText(example())
                .replace("<param name=\"message\">speed</param>\n        <param name=\"expression\">",
                        "<param name=\"message\">brake</param>\n        <param name=\"expression\">"), "brake");
        assertThat(NetworkRepository.toText(n)).contains("brake");
        MemoryEventSink sink = new MemoryEventSink();
        try (RuntimeNetwork net = start(n, sink)) {
            eventually("the refusal reported", () -> sink.events(RelationValueEvent.class).stream()
                    .anyMatch(e -> e.value().equals("refused: servant planner/speed answers 'brake', not 'speed'")));
            assertThat(net.controller().value(ref("Speed")).asDouble()).isEqualTo(0.0);
        }
    }

    private static Value ask(RuntimeNetwork net, String message, double argument) throws Exception {
        CompletableFuture<Value> reply = new CompletableFuture<>();
        net.servantRegistry().sendMessage("planner/speed", message, Value.of(argument),
                ReturnListener.of(reply::complete, r -> reply.completeExceptionally(new MessageRefusedException(r))));
        return reply.get(10, TimeUnit.SECONDS);
    }
}

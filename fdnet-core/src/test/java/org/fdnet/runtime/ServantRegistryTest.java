package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;

class ServantRegistryTest {
    private final ServantRegistry registry = new ServantRegistry(() -> null);

    /** A servant class: registered by name, instantiated on demand. */
    public static final class Doubler implements MessageServant {
        @Override
        public Value answer(String message, Value argument) {
            if (!message.equals("double")) {
                throw new MessageRefusedException("Doubler answers 'double', not '" + message + "'");
            }
            return Value.of(2 * argument.asDouble());
        }
    }

    @AfterEach
    void close() {
        registry.close();
    }

    private Value ask(String path, String message, double argument) throws Exception {
        CompletableFuture<Value> reply = new CompletableFuture<>();
        registry.sendMessage(path, message, Value.of(argument),
                ReturnListener.of(reply::complete, r -> reply.completeExceptionally(new MessageRefusedException(r))));
        return reply.get(10, TimeUnit.SECONDS);
    }

    @Test
    void shouldNameInstancesOfAServantClassByTheFirstFreeNumber() {
        registry.setServantClass("doubler", Doubler.class);
        assertThat(registry.containsServantClass("doubler")).isTrue();
        ServantNode first = registry.instantiate("doubler");
        ServantNode second = registry.instantiate("doubler");
        assertThat(first.name()).isEqualTo("doubler:1");
        assertThat(second.name()).isEqualTo("doubler:2");
        registry.releaseServantInstance("doubler:1");
        assertThat(registry.getServantInstance("doubler:1")).isNull();
        assertThat(registry.instantiate("doubler").name()).isEqualTo("doubler:1");
        assertThat(registry.getRootServant().children()).extracting(ServantNode::name).contains("doubler:1", "doubler:2");
    }

    @Test
    void shouldFindServantsByPathFromTheRootAndMakeRegisteredClassesOnDemand() {
        ServantNode speed = registry.offer("planner/speed", (m, a) -> a);
        assertThat(speed.path()).isEqualTo("/planner/speed");
        assertThat(speed.getRootServant()).isSameAs(registry.getRootServant());
        assertThat(speed.getParent().answers()).isFalse();
        assertThat(registry.getServant("/planner/speed")).isSameAs(speed);
        registry.setServantClass("doubler", Doubler.class);
        ServantNode made = registry.getServant("planner/doubler");
        assertThat(made.getParent()).isSameAs(speed.getParent());
        assertThat(registry.getServant("planner/doubler")).isSameAs(made);
        assertThatThrownBy(() -> registry.getServant("planner/nothing")).hasMessage("no servant at /planner/nothing");
        assertThatThrownBy(() -> registry.offer("planner/speed", (m, a) -> a)).hasMessageContaining("is taken");
        assertThatThrownBy(() -> registry.offer("a//b", (m, a) -> a)).hasMessageContaining("must be non-empty");
    }

    @Test
    void shouldAnswerMessagesAsynchronouslyThroughTheReturnListener() throws Exception {
        registry.setServantClass("doubler", Doubler.class);
        assertThat(ask("doubler", "double", 21).asDouble()).isEqualTo(42.0);
        assertThatThrownBy(() -> ask("doubler", "halve", 1)).hasRootCauseMessage("Doubler answers 'double', not 'halve'");
        assertThatThrownBy(() -> ask("nobody", "double", 1)).hasRootCauseMessage("no servant at nobody in this network");
    }

    @Test
    void shouldRefuseMessagesToAWithdrawnServantAndAfterClose() throws Exception {
        ServantNode echo = registry.offer("echo", (m, a) -> a);
        assertThat(ask("echo", "any", 3).asDouble()).isEqualTo(3.0);
        registry.withdraw(echo);
        assertThatThrownBy(() -> ask("echo", "any", 3)).hasRootCauseMessage("no servant at echo in this network");
        registry.close();
        assertThatThrownBy(() -> ask("echo", "any", 3)).hasRootCauseMessage("the network has stopped: message any to echo not sent");
    }

    @Test
    void shouldTellEveryListenerWhenTheNetworkStopsWithMessagesStillWaiting() throws Exception {
        CountDownLatch entered = new CountDownLatch(1);
        CountDownLatch never = new CountDownLatch(1);
        registry.offer("slow", (m, a) -> {
            entered.countDown();
            try {
                never.await();
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
                throw new MessageRefusedException("slow was interrupted");
            }
            return a;
        });
        List<CompletableFuture<String>> outcomes = new ArrayList<>();
        for (int i = 0; i < 3; i++) {
            CompletableFuture<String> outcome = new CompletableFuture<>();
            registry.sendMessage("slow", "m" + i, Value.of(i), ReturnListener.of(v -> outcome.complete("answered"), outcome::complete));
            outcomes.add(outcome);
        }
        assertThat(entered.await(10, TimeUnit.SECONDS)).isTrue();
        registry.close();
        List<String> told = new ArrayList<>();
        for (CompletableFuture<String> outcome : outcomes) {
            told.add(outcome.get(10, TimeUnit.SECONDS));
        }
        assertThat(told).doesNotContain("answered").contains("the network has stopped: message m2 to slow not sent");
    }
}

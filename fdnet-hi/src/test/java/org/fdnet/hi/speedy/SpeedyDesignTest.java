package org.fdnet.hi.speedy;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

class SpeedyDesignTest {
    private final List<String> log = new ArrayList<>();
    private final SpeedyDesign handler = new SpeedyDesign();

    private Updatable component(String name, Updatable... parents) {
        Updatable c = () -> log.add(name);
        handler.register(name, c, parents);
        return c;
    }

    @Test
    void shouldUpdateEachDescendantOnceInADiamondParentsFirst() {
        // A → B, A → C, B → D, C → D: D has two parents and must update once, after both
        Updatable a = component("A");
        Updatable b = component("B", a);
        Updatable c = component("C", a);
        component("D", b, c);

        handler.changed(a);

        assertThat(log).containsExactly("B", "C", "D");
    }

    @Test
    void shouldUpdateAChainInOrderAndNotTheSourceItself() {
        Updatable a = component("A");
        Updatable b = component("B", a);
        Updatable c = component("C", b);
        component("D", c);

        handler.changed(b);

        assertThat(log).containsExactly("C", "D");
    }

    @Test
    void shouldOrderByLongestChainNotByRegistration() {
        // E depends on A directly and on D, which is three levels down: E must wait for D
        Updatable a = component("A");
        Updatable b = component("B", a);
        Updatable c = component("C", b);
        Updatable d = component("D", c);
        Updatable e = component("E", a);
        handler.dependsOn(e, d);

        handler.changed(a);

        assertThat(log).containsExactly("B", "C", "D", "E");
    }

    @Test
    void shouldLeaveComponentsOfAnotherRootAlone() {
        Updatable a = component("A");
        Updatable x = component("X");
        component("B", a);
        component("Y", x);
        component("Both", a, x);

        handler.changed(x);

        assertThat(log).containsExactly("Y", "Both");
    }

    @Test
    void shouldRefuseALoopNamingIt() {
        Updatable a = component("A");
        Updatable b = component("B", a);
        Updatable c = component("C", b);

        assertThatThrownBy(() -> handler.dependsOn(a, c)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("A → B → C → A");
        assertThatThrownBy(() -> handler.dependsOn(a, a)).isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("loop");
        // the refused dependency changed nothing
        handler.changed(c);
        assertThat(log).isEmpty();
    }

    @Test
    void shouldRefuseUnregisteredParentsAndDoubleRegistration() {
        Updatable stranger = () -> log.add("stranger");
        assertThatThrownBy(() -> handler.register("B", () -> { }, stranger))
                .hasMessageContaining("not registered");
        Updatable a = component("A");
        assertThatThrownBy(() -> handler.register("again", a)).hasMessageContaining("registered already as 'A'");
    }

    @Test
    void shouldIgnoreAChangeReportedByAComponentWhileTheCascadeUpdatesIt() {
        // a Swing field fires its listener when its text is set during update(): its children are in the cascade
        Updatable a = component("A");
        Updatable[] b = new Updatable[1];
        b[0] = () -> {
            log.add("B");
            handler.changed(b[0]);
        };
        handler.register("B", b[0], a);
        component("C", b[0]);

        handler.changed(a);

        assertThat(log).containsExactly("B", "C");
    }

    @Test
    void shouldRunAChangeFromOutsideTheCascadeAfterIt() {
        Updatable a = component("A");
        Updatable x = component("X");
        component("Y", x);
        Updatable b = () -> {
            log.add("B");
            handler.changed(x);
        };
        handler.register("B", b, a);

        handler.changed(a);

        assertThat(log).containsExactly("B", "Y");
    }

    @Test
    void shouldUpdateEveryComponentOnceWhenAFrameOpens() {
        Updatable a = component("A");
        Updatable b = component("B", a);
        component("C", a, b);

        handler.updateAll();

        assertThat(log).containsExactly("A", "B", "C");
    }
}

package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.fdnet.runtime.TestNetworks.*;

import java.nio.file.Path;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** networks/nested-arm.fdn run: Arm and Arm/Hand at start, Fingers and Wrist on request. */
@Timeout(30)
class NestedModulesRuntimeTest {

    private static NetworkInfo example() throws Exception {
        return NetworkRepository.load(Path.of("../networks/nested-arm.fdn"));
    }

    @Test
    void shouldStartTheModulesLoadedAtStartDownTheTree() throws Exception {
        try (RuntimeNetwork net = start(example(), null)) {
            Controller c = net.controller();
            assertThat(c.loadedModules()).containsExactly("main", "Arm", "Arm/Hand");
            c.setValue(ref("Clock"), "3");
            quiet(net);
            assertThat(c.value(ref("Arm/Hand/Grip")).asDouble()).isEqualTo(16.0);
            assertThat(c.value(ref("Arm/Hand/Fingers/Tip"))).isNull();
        }
    }

    @Test
    void shouldUnloadEveryModuleBelowAndLoadOnlyLoadAtStartChildrenAgain() throws Exception {
        try (RuntimeNetwork net = start(example(), null)) {
            Controller c = net.controller();
            assertThat(c.load("Arm/Hand/Fingers").executed()).isTrue();
            assertThat(c.load("Arm/Wrist").executed()).isTrue();
            assertThat(c.unload("Arm").executed()).isTrue();
            assertThat(c.loadedModules()).containsExactly("main");
            assertThat(c.value(ref("Arm/Hand/Fingers/Tip"))).isNull();
            assertThat(c.load("Arm").executed()).isTrue();
            assertThat(c.loadedModules()).containsExactly("main", "Arm", "Arm/Hand");
        }
    }

    @Test
    void shouldRefuseToLoadAChildWhoseParentIsNotLoaded() throws Exception {
        try (RuntimeNetwork net = start(example(), null)) {
            Controller c = net.controller();
            c.unload("Arm");
            ChangeOutcome outcome = c.load("Arm/Hand/Fingers");
            assertThat(outcome.executed()).isFalse();
            assertThat(outcome.reason()).contains("inside module 'Arm/Hand', which is not loaded");
        }
    }

    @Test
    void shouldRunANestedModuleLoadedWhileRunningReadingItsParentsData() throws Exception {
        try (RuntimeNetwork net = start(example(), null)) {
            Controller c = net.controller();
            assertThat(c.load("Arm/Hand/Fingers").executed()).isTrue();
            c.setValue(ref("Clock"), "1");
            quiet(net);
            assertThat(c.value(ref("Arm/Hand/Fingers/Tip")).asDouble()).isEqualTo(6.0);
        }
    }
}

package org.fdnet.runtime;

import static org.assertj.core.api.Assertions.assertThat;
import static org.fdnet.runtime.TestNetworks.ref;

import java.nio.file.Path;
import java.util.List;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.runtime.loading.ClassLoadingPolicy;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The thesis's Figure 5 as shipped in networks/roq-motion.fdn: it runs, loops, and survives module churn. */
@Timeout(30)
class RoqMotionTest {
    private static final Path FILE = Path.of("../networks/roq-motion.fdn");

    @Test
    void shouldCloseThePostureLoopAndReactToTheJudgment() throws Exception {
        RuntimeOptions o = RuntimeOptions.defaults().classLoading(ClassLoadingPolicy.forNetworkFile(FILE, List.of()));
        try (RuntimeNetwork net = RuntimeNetwork.start(NetworkRepository.load(FILE), o)) {
            Controller c = net.controller();
            Thread.sleep(400);
            long postureValues = net.firings();
            Value posture = c.value(ref("A present posture"));
            assertThat(posture.length()).isEqualTo(4);
            assertThat(posture.time()).isPositive();
            for (double leg : posture.asDoubles()) {
                assertThat(leg).isBetween(0.2, 0.4);
            }
            // standing still: with no wish to walk the judgment is 0 and the posture follows balance alone
            c.setValue(ref("Walk/I want to walk"), "0");
            Thread.sleep(200);
            assertThat(c.value(ref("Integration/judgment")).asDouble()).isZero();
            // unload Walk: judge and integrate report the missing Datas; load it: they run again
            assertThat(c.unload("Walk").executed()).isTrue();
            assertThat(c.relationState(ref("Integration/judge")).text()).isEqualTo("WAITING: missing Walk/I want to walk");
            assertThat(c.relationState(ref("Integration/integrate")).status()).isEqualTo(RelationStatus.WAITING);
            assertThat(c.load("Walk").executed()).isTrue();
            assertThat(c.relationState(ref("Integration/integrate")).status()).isEqualTo(RelationStatus.RUNNING);
            Thread.sleep(200);
            assertThat(net.firings()).isGreaterThan(postureValues);
            assertThat(c.relationStates()).noneMatch(s -> s.status() == RelationStatus.FAILED);
        }
    }
}

package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The example networks over several hosts, each run by {@code fdnet run} across two {@code fdnet host} processes. */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class TwoRobotsExampleTest {
    private static final Pattern SPEED = Pattern.compile("main/Speed=(-?[0-9.]+)");
    private CorbaCluster cluster;

    @AfterEach
    void stop() {
        if (cluster != null) {
            cluster.close();
        }
    }

    @Test
    void shouldRunTheFlyerAndCrawlerExampleAcrossTwoHostProcesses() {
        cluster = CorbaCluster.start();
        cluster.startHost("flyer");
        cluster.startHost("crawler");

        try (FdnetChildProcess run = FdnetChildProcess.start("run two-robots",
                List.of("run", "../networks/two-robots.fdn", "--naming", cluster.corbaloc(), "--as", "operator-station",
                        "--for", "8s"), "running on 3 hosts", 60_000)) {
            assertThat(run.awaitExit(60_000)).isZero();
            List<String> out = run.output();
            assertThat(out).anyMatch(l -> l.startsWith("running on 3 hosts: flyer (2 nodes, 0 stand-ins), "
                    + "crawler (4 nodes, 1 stand-ins), operator-station (1 nodes, 2 stand-ins)"));
            // The crawler's Relations used the flyer's map: the operator saw a certainty computed from it.
            assertThat(out).anyMatch(l -> l.startsWith("[operator]") && !l.endsWith("main/Certainty=0.0000"));
            assertThat(out).noneMatch(l -> l.contains("BROKEN"));
            assertThat(out).anyMatch(l -> l.contains("crawler:main/Heading -> operator-station (link 2)") && l.endsWith("ok"));
        }
    }

    /**
     * {@code networks/servant-messages-two-hosts.fdn}: Driver on host "driver" messages the servant Planner offers on
     * host "planner", through the run's coordinator.
     */
    @Test
    void shouldAnswerADriversMessagesWithThePlannersServantOnAnotherHost() {
        cluster = CorbaCluster.start();
        cluster.startHost("planner");
        cluster.startHost("driver");

        try (FdnetChildProcess run = FdnetChildProcess.start("run servant-messages",
                List.of("run", "../networks/servant-messages-two-hosts.fdn", "--naming", cluster.corbaloc(),
                        "--as", "operator", "--for", "6s"), "running on 3 hosts", 60_000)) {
            assertThat(run.awaitExit(60_000)).isZero();
            List<String> out = run.output();
            assertThat(out).anyMatch(l -> l.startsWith("running on 3 hosts: planner (2 nodes"));
            // every reply is min(Wish, 0.5 * Obstacle) computed on host planner: above 0, never above 2
            List<Double> speeds = out.stream().filter(l -> l.startsWith("[operator]")).map(SPEED::matcher)
                    .filter(Matcher::find).map(m -> Double.parseDouble(m.group(1))).toList();
            assertThat(speeds).isNotEmpty().allMatch(s -> s <= 2.0).anyMatch(s -> s > 0.0);
            assertThat(out).noneMatch(l -> l.contains("refused"));
        }
    }
}

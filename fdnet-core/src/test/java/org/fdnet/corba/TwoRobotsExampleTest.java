package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** {@code networks/two-robots.fdn} run by {@code fdnet run} across two {@code fdnet host} processes. */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class TwoRobotsExampleTest {
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
}

package org.fdnet.corba;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.fdnet.corba.control.RemoteLiveNetwork;
import org.fdnet.corba.control.RunFiles;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.testing.HeardFromNetwork;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import static org.assertj.core.api.Assertions.assertThat;


/**
 * A distributed run registers its control object in its naming service under the network's name: a tool finds it
 * there, holds and resumes a module on every host through it, hears the changes and the hosts' values, and is told
 * when the run stops.
 */
@Timeout(value = 180, unit = TimeUnit.SECONDS)
class DistributedRunControlTest {
    private static final NodeRef MAP = new NodeRef("main", "Map");

    @TempDir
    Path noRunFiles;

    private CorbaCluster cluster;
    private FdnetChildProcess run;
    private RemoteLiveNetwork network;

    @AfterEach
    void stop() {
        System.clearProperty(RunFiles.FOLDER_PROPERTY);
        if (network != null) {
            network.close();
        }
        if (run != null) {
            run.close();
        }
        if (cluster != null) {
            cluster.close();
        }
    }

    @Test
    void shouldBeFoundInTheNamingServiceAndHoldAModuleOnEveryHost() throws Exception {
        cluster = CorbaCluster.start();
        cluster.startHost("flyer");
        cluster.startHost("crawler");
        run = FdnetChildProcess.start("run two-robots", List.of("run", "../networks/two-robots.fdn", "--naming",
                cluster.corbaloc(), "--as", "operator-station", "--for", "150s"), "control object of", 60_000);
        // this JVM sees no ~/.fdnet/run files: the name must come from the naming service
        System.setProperty(RunFiles.FOLDER_PROPERTY, noRunFiles.toString());

        network = RemoteLiveNetwork.attach("two-robots", cluster.corbaloc());

        assertThat(network.name()).isEqualTo("two-robots");
        assertThat(network.snapshot().node(new NodeRef("main", "ChooseSector"))).isNotNull();
        HeardFromNetwork heard = new HeardFromNetwork();
        network.subscribe(heard);
        assertThat(heard.sampleWith(MAP)).as("the flyer's Map, read from its host").isTrue();

        ChangeOutcome held = network.hold("main");
        assertThat(held.executed()).as(held.toString()).isTrue();
        assertThat(held.description()).contains("flyer", "crawler", "operator-station");
        assertThat(network.heldModules()).containsExactly("main");
        assertThat(heard.changes.poll(15, TimeUnit.SECONDS)).isEqualTo(held);
        assertThat(network.resume("main").executed()).isTrue();
        ChangeOutcome load = network.load("Nothing");
        assertThat(load.executed()).isFalse();
        assertThat(load.reason()).contains("no module named 'Nothing'");

        NetworkInfo base = network.snapshot();
        NetworkInfo edited = base.copy();
        edited.addModule("Spare", false);
        ChangeOutcome added = network.apply("add module Spare", base, edited);
        assertThat(added.executed()).as(added.toString()).isTrue();
        assertThat(network.snapshot().module("Spare")).as("the edit is in the running definition").isNotNull();
        ChangeOutcome stale = network.apply("add module Spare again", base, edited);
        assertThat(stale.executed()).as("the network already has what the stale edit adds").isFalse();

        run.close();
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(15);
        while (heard.disconnects.isEmpty() && System.nanoTime() < deadline) {
            Thread.sleep(50);
        }
        assertThat(heard.disconnects).hasSize(1);
        assertThat(heard.disconnects.get(0)).contains("two-robots");
    }

}

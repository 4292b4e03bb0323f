package org.fdnet.corba;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Arrays;
import java.util.HashSet;
import java.util.List;
import java.util.Set;
import java.util.concurrent.TimeUnit;
import java.util.function.Predicate;
import org.fdnet.corba.idl.ChangeOp;
import org.fdnet.corba.idl.ChangeRequest;
import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.NodeId;
import org.fdnet.netinfo.NodeRef;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * Live changes of {@code networks/two-robots.fdn} while it runs over three processes, typed on {@code fdnet run}'s
 * standard input: a module is held and resumed on every host it has nodes on, or refused with the reason and
 * left as it was everywhere.
 */
@Timeout(value = 180, unit = TimeUnit.SECONDS)
class LiveChangesAcrossHostsTest {
    private static final NodeId MAP = IdlMapping.id(new NodeRef("main", "Map"));

    private CorbaCluster cluster;
    private FdnetChildProcess run;
    private final Set<Integer> answered = new HashSet<>(); // output lines already taken as an answer

    @AfterEach
    void stop() {
        if (run != null) {
            run.close();
        }
        if (cluster != null) {
            cluster.close();
        }
    }

    @Test
    void shouldHoldAndResumeAModuleOnEveryHostOrRefuseItChangingNothing() throws Exception {
        cluster = CorbaCluster.start();
        Host flyer = cluster.startHost("flyer");
        Host crawler = cluster.startHost("crawler");
        run = FdnetChildProcess.start("run two-robots", List.of("run", "../networks/two-robots.fdn", "--naming",
                cluster.corbaloc(), "--as", "operator-station", "--for", "120s"), "running on 3 hosts", 60_000);
        awaitChange(flyer);

        run.send("hold main");
        String held = awaitLine(l -> l.startsWith("ok: hold main") || l.startsWith("refused: hold main"));
        assertThat(held).startsWith("ok: hold main on").contains("flyer").contains("crawler").contains("operator-station");
        // Held on the flyer: Survey writes no more Map values, however long we look.
        Object mapWhileHeld = read(flyer);
        Thread.sleep(1_000);
        assertThat(read(flyer)).isEqualTo(mapWhileHeld);

        run.send("hold main");
        assertThat(awaitLine(l -> l.startsWith("refused: hold main")))
                .contains("already on hold").contains("nothing changed on any host");

        run.send("resume main");
        assertThat(awaitLine(l -> l.startsWith("ok: resume main"))).contains("flyer").contains("crawler");
        awaitChange(flyer);

        // One host refuses: the flyer alone is put on hold behind the run's back, then "hold main" is typed.
        // The crawler could hold but must not: it is asked to prepare, then told to abort.
        ChangeRequest holdOnFlyerOnly = new ChangeRequest(1, ChangeOp.CO_HOLD, "main", new NodeId("", ""), "", "");
        assertThat(flyer.prepareChange(holdOnFlyerOnly)).isEmpty();
        flyer.commitChange(1);
        run.send("hold main");
        assertThat(awaitLine(l -> l.startsWith("refused: hold main") && l.contains("host flyer")))
                .contains("nothing changed on any host");
        ChangeRequest resumeProbe = new ChangeRequest(2, ChangeOp.CO_RESUME, "main", new NodeId("", ""), "", "");
        assertThat(crawler.prepareChange(resumeProbe)).contains("not on hold on host crawler");

        run.send("hold Nowhere");
        assertThat(awaitLine(l -> l.startsWith("refused: hold Nowhere"))).contains("runs on no host");
        run.send("set Survey/period=50");
        assertThat(awaitLine(l -> l.contains("main/Survey:period=50"))).startsWith("ok: set main/Survey:period=50 on flyer");
        run.send("send Certainty=0.5");
        assertThat(awaitLine(l -> l.contains("send main/Certainty=0.5"))).isEqualTo("ok: send main/Certainty=0.5 on crawler");
        run.send("send Certainty=not-a-number");
        assertThat(awaitLine(l -> l.contains("send main/Certainty=not-a-number"))).startsWith("refused:");
        run.send("send Ghost=1");
        assertThat(awaitLine(l -> l.contains("send main/Ghost=1"))).startsWith("refused:").contains("runs on no host");
        run.send("help");
        awaitLine(l -> l.contains("resume MODULE"));
    }

    private static Object read(Host host) throws Exception {
        Object v = ValueCodec.decode(host.read(MAP));
        return v instanceof double[] d ? Arrays.toString(d) : v;
    }

    /** Waits (bounded) until the flyer's Map takes a new value: Survey runs there. */
    private static void awaitChange(Host flyer) throws Exception {
        Object first = read(flyer);
        long deadline = System.currentTimeMillis() + 30_000;
        while (read(flyer).equals(first)) {
            assertThat(System.currentTimeMillis()).as("Map changes on the flyer").isLessThan(deadline);
            Thread.sleep(50);
        }
    }

    /** networks/nested-arm.fdn with module Arm and everything in it on host "flyer". */
    @Test
    void shouldLoadAndUnloadNestedModulesOnTheirHostAsOneHostDoes(@TempDir Path dir) throws Exception {
        String text = Files.readString(Path.of("../networks/nested-arm.fdn"), StandardCharsets.UTF_8);
        int arm = text.indexOf("<module name=\"Arm\"");
        Path nested = dir.resolve("nested-arm.fdn");
        Files.writeString(nested, text.substring(0, arm) + text.substring(arm).replace("<host>localhost</host>", "<host>flyer</host>"),
                StandardCharsets.UTF_8);
        cluster = CorbaCluster.start();
        Host flyer = cluster.startHost("flyer");
        run = FdnetChildProcess.start("run nested-arm", List.of("run", nested.toString(), "--naming", cluster.corbaloc(),
                "--as", "operator-station", "--for", "120s"), "running on 2 hosts", 60_000);
        assertThat(flyer.nodes()).contains("Arm/Shoulder", "Arm/Hand/Grip").doesNotContain("Arm/Hand/Fingers/Tip");
        run.send("load Arm/Hand/Fingers");
        assertThat(awaitLine(l -> l.contains("Arm/Hand/Fingers"))).isEqualTo("ok: load Arm/Hand/Fingers on flyer");
        assertThat(flyer.nodes()).contains("Arm/Hand/Fingers/Tip");
        run.send("unload Arm");
        assertThat(awaitLine(l -> l.contains("unload Arm"))).startsWith("ok: unload Arm");
        assertThat(flyer.nodes()).noneMatch(n -> n.startsWith("Arm/"));
        run.send("load Arm/Hand");
        assertThat(awaitLine(l -> l.contains("load Arm/Hand"))).isEqualTo("refused: load Arm/Hand: module 'Arm/Hand' is "
                + "inside module 'Arm', which is not loaded: load 'Arm' first");
        run.send("load Arm");
        assertThat(awaitLine(l -> l.startsWith("ok: load Arm "))).isEqualTo("ok: load Arm on flyer");
        assertThat(flyer.nodes()).contains("Arm/Hand/Grip").doesNotContain("Arm/Hand/Fingers/Tip");
    }

    private String awaitLine(Predicate<String> line) throws InterruptedException {
        long deadline = System.currentTimeMillis() + 30_000;
        while (true) {
            List<String> out = run.output();
            for (int i = out.size() - 1; i >= 0; i--) {
                if (line.test(out.get(i)) && !answered.contains(i)) {
                    answered.add(i);
                    return out.get(i);
                }
            }
            assertThat(System.currentTimeMillis()).as(String.join("\n", out)).isLessThan(deadline);
            Thread.sleep(50);
        }
    }
}

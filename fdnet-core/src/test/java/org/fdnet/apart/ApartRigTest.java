package org.fdnet.apart;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/** The rig on this machine's kernel: real namespaces, veth pairs, bridge, nftables and TBF (needs root). */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class ApartRigTest {
    private static final String PREFIX = "fdnrigtest";
    private static final int PORT = 4711;
    private static final int CONNECT_TIMEOUT_MS = 1500;

    private final List<Process> listeners = new ArrayList<>();
    private ApartRig rig;

    @AfterEach
    void cleanUp() {
        listeners.forEach(Process::destroyForcibly);
        if (rig != null) {
            rig.close();
        }
    }

    @Test
    void shouldLetTwoHostsReachEachOtherByTcpOnTheirOwnAddresses() throws Exception {
        rig = ApartRig.create(PREFIX, List.of("a", "b"));
        assertFalse(rig.address("a").isLoopbackAddress());
        assertFalse(rig.address("a").equals(rig.address("b")));
        listen("a");
        assertEquals("connected", connect("b", "a"));
    }

    @Test
    void shouldLetAConnectionToABlackholedHostTimeOutWithoutAResetAndHealIt() throws Exception {
        rig = ApartRig.create(PREFIX, List.of("a", "b"));
        listen("a");
        rig.blackhole("a");
        assertEquals(List.of("fdnet_apart_blackhole"), rig.faultTables("a"));
        long start = System.nanoTime();
        assertEquals("timed out", connect("b", "a"));
        assertTrue(System.nanoTime() - start >= TimeUnit.MILLISECONDS.toNanos(CONNECT_TIMEOUT_MS));
        rig.heal("a");
        assertEquals(List.of(), rig.faultTables("a"));
        assertEquals("connected", connect("b", "a"));
    }

    @Test
    void shouldDropEverythingAtFullLossAndLiftEachFaultOnClear() throws Exception {
        rig = ApartRig.create(PREFIX, List.of("a", "b"));
        listen("a");
        rig.loss("a", 100);
        assertEquals("timed out", connect("b", "a"));
        rig.throttle("a", 1000);
        assertTrue(rig.queue("a").contains("tbf") && rig.queue("a").contains("rate 1Mbit"), rig.queue("a"));
        rig.clear("a");
        assertEquals(List.of(), rig.faultTables("a"));
        assertFalse(rig.queue("a").contains("tbf"), rig.queue("a"));
        assertEquals("connected", connect("b", "a"));
    }

    @Test
    void shouldSlowAThrottledLinkToItsRate() throws Exception {
        rig = ApartRig.create(PREFIX, List.of("a", "b"));
        listen("a");
        int bytes = 256 * 1024;
        long unthrottled = send("b", "a", bytes);
        rig.throttle("a", 1000);
        long throttled = send("b", "a", bytes);
        // 256 KiB at 1 Mbit/s is 2.1 s; the bucket lets its first 16 KiB through at once
        assertTrue(throttled >= 1800, "256 KiB over a 1 Mbit/s link took " + throttled + " ms");
        assertTrue(unthrottled < throttled / 4, "unthrottled " + unthrottled + " ms, throttled " + throttled + " ms");
    }

    @Test
    void shouldRefuseAnUnknownHostAndBadFaultsByName() {
        rig = ApartRig.create(PREFIX, List.of("a"));
        assertTrue(assertThrows(IllegalArgumentException.class, () -> rig.blackhole("z")).getMessage()
                .contains("no host 'z'"));
        assertThrows(IllegalArgumentException.class, () -> rig.loss("a", 101));
        assertThrows(IllegalArgumentException.class, () -> rig.throttle("a", 0));
        assertThrows(IllegalArgumentException.class, () -> ApartRig.create("bad-prefix", List.of("a")));
        assertThrows(IllegalArgumentException.class, () -> ApartRig.create(PREFIX, List.of("a", "a")));
    }

    @Test
    void shouldLeaveNoNamespaceOrLinkBehindOnClose() throws Exception {
        String linksBefore = rootLinks();
        rig = ApartRig.create(PREFIX, List.of("a", "b", "c"));
        String rigNamespace = rig.rigNamespace();
        listen("a");
        rig.blackhole("b");
        rig.throttle("c", 500);
        assertEquals(4, namespacesOf(rigNamespace).size());
        rig.close();
        rig = null;
        assertEquals(List.of(), namespacesOf(rigNamespace));
        assertEquals(linksBefore, rootLinks());
        assertFalse(listeners.get(0).isAlive(), "a process left in a host's namespace is ended with it");
    }

    @Test
    void shouldSweepTheLeftoversOfADeadRigAndKeepALiveOne() throws Exception {
        Process gone = new ProcessBuilder("true").start();
        gone.waitFor();
        String dead = PREFIX + "-" + gone.pid();
        SystemCommand.run("ip", "netns", "add", dead);
        SystemCommand.run("ip", "netns", "add", dead + "-a");
        rig = ApartRig.create(PREFIX, List.of("a"));
        assertEquals(List.of(), namespacesOf(dead), "create sweeps its prefix first");

        SystemCommand.run("ip", "netns", "add", dead + "-b");
        assertEquals(List.of(dead + "-b"), ApartRig.sweep(PREFIX));
        assertEquals(2, namespacesOf(rig.rigNamespace()).size(), "the live rig stays");
        assertEquals("connected", connectAfterListening());
    }

    @Test
    void shouldRefuseInOneLineSayingWhatRootIsNeededForWhenNotRoot(@TempDir Path dir) throws Exception {
        // The probe runs as nobody, who cannot read the local Maven repository: its one library is copied.
        Path slf4j = Path.of(List.of(System.getProperty("java.class.path").split(":")).stream()
                .filter(p -> p.contains("slf4j-api")).findFirst().orElseThrow());
        Files.copy(slf4j, dir.resolve("slf4j-api.jar"));
        Files.setPosixFilePermissions(dir, PosixFilePermissions.fromString("rwxr-xr-x"));
        Files.setPosixFilePermissions(dir.resolve("slf4j-api.jar"), PosixFilePermissions.fromString("rw-r--r--"));
        String classPath = String.join(":", Path.of("target", "classes").toAbsolutePath().toString(),
                Path.of("target", "test-classes").toAbsolutePath().toString(), dir.resolve("slf4j-api.jar").toString());
        Process p = new ProcessBuilder("setpriv", "--reuid=65534", "--regid=65534", "--clear-groups",
                Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Dslf4j.internal.verbosity=ERROR",
                "-cp", classPath, NotRootProbe.class.getName()).redirectError(ProcessBuilder.Redirect.DISCARD).start();
        String out = new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        assertEquals(List.of("the apart rig needs root: it makes network namespaces, veth pairs, a bridge and nftables"
                + " rules to put hosts on addresses of their own (run it as root)"), out.lines().toList());
    }

    private String connectAfterListening() throws Exception {
        listen("a");
        return connect("a", "a");
    }

    private void listen(String host) throws IOException {
        Process p = java(host, "listen", rig.address(host).getHostAddress(), Integer.toString(PORT));
        listeners.add(p);
        String first = new String(p.getInputStream().readNBytes("listening".length()), StandardCharsets.UTF_8);
        assertEquals("listening", first, "the listener on " + host + " did not start");
    }

    private String connect(String from, String to) throws Exception {
        Process p = java(from, "connect", rig.address(to).getHostAddress(), Integer.toString(PORT),
                Integer.toString(CONNECT_TIMEOUT_MS));
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        return new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip();
    }

    /** Milliseconds {@code bytes} took from {@code from} to the listener on {@code to}. */
    private long send(String from, String to, int bytes) throws Exception {
        Process p = java(from, "send", rig.address(to).getHostAddress(), Integer.toString(PORT), Integer.toString(bytes));
        assertTrue(p.waitFor(60, TimeUnit.SECONDS));
        return Long.parseLong(new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8).strip());
    }

    private Process java(String host, String... args) throws IOException {
        List<String> argv = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-XX:TieredStopAtLevel=1", "-XX:+UseSerialGC", "-cp", System.getProperty("java.class.path"),
                TcpEnd.class.getName()));
        argv.addAll(List.of(args));
        return new ProcessBuilder(rig.command(host, argv)).redirectError(ProcessBuilder.Redirect.DISCARD).start();
    }

    private static List<String> namespacesOf(String rigNamespace) {
        return Namespaces.list().stream().filter(n -> n.equals(rigNamespace) || n.startsWith(rigNamespace + "-"))
                .toList();
    }

    private static String rootLinks() {
        return SystemCommand.run("ip", "-o", "link", "show").lines().map(l -> l.replaceAll("qlen [0-9]+", ""))
                .map(l -> l.split(" ")[1]).sorted().toList().toString();
    }
}

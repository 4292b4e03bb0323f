package org.fdnet.run;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.PrintWriter;
import java.io.StringWriter;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import java.util.concurrent.TimeUnit;
import org.fdnet.control.LiveNetwork;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.corba.OrbSettings;
import org.fdnet.corba.control.RemoteLiveNetwork;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

/**
 * Every {@code fdnet run} option in a distributed run: a network whose Datas and Relations live on host
 * {@code flyer} (a child process) and whose {@code Operator} runs in this JVM's {@link NetworkRun}, which reads
 * the flyer's Datas through stand-ins. Each option either works across hosts or is refused by name.
 */
@Timeout(value = 150, unit = TimeUnit.SECONDS)
class DistributedRunOptionsTest {
    private static final String NETWORK = """
            <?xml version="1.0" encoding="UTF-8"?>
            <cnet name="options-test">
                <dstructure><name>Level</name><host>flyer</host><path></path>
                    <class>org.fdnet.runtime.library.DoubleData</class></dstructure>
                <dstructure><name>Goal</name><host>flyer</host><path></path>
                    <class>org.fdnet.runtime.library.DoubleData</class></dstructure>
                <pstructure><name>Source</name><host>flyer</host><path></path>
                    <class>org.fdnet.runtime.library.Expression</class>
                    <param name="period" type="long">50</param><param name="expression">1</param></pstructure>
                <pstructure><name>Operator</name><host>localhost</host><path></path>
                    <class>org.fdnet.runtime.library.Print</class>
                    <param name="prefix">operator</param><param name="every" type="long">1000</param></pstructure>
                <connection>
                    <write><data>Level</data><proc>Source</proc></write>
                    <read><data>Level</data><proc>Operator</proc></read>
                    <read><data>Goal</data><proc>Operator</proc></read>
                </connection>
                <module name="Extra" loadatstart="no">
                    <dstructure><name>Spare</name><host>flyer</host><path></path>
                        <class>org.fdnet.runtime.library.DoubleData</class></dstructure>
                </module>
            </cnet>
            """;

    @TempDir
    static Path folder;

    private static final List<FdnetChildProcess> processes = new ArrayList<>();
    private static String naming;
    private static FdnetChildProcess flyer;
    private static Path file;

    @BeforeAll
    static void startNamingAndFlyer() throws Exception {
        file = Files.writeString(folder.resolve("options-test.fdn"), NETWORK);
        int port = FdnetChildProcess.freePort();
        processes.add(FdnetChildProcess.start("naming", List.of("naming", "--port", Integer.toString(port)),
                "fdnet naming ready", 60_000));
        naming = OrbSettings.namingCorbaloc(OrbSettings.LOOPBACK, port);
        flyer = FdnetChildProcess.start("host flyer", List.of("host", "--name", "flyer", "--naming", naming,
                "--workers", "2"), "fdnet host flyer ready", 60_000);
        processes.add(flyer);
    }

    @AfterAll
    static void stopEveryProcess() {
        for (int i = processes.size() - 1; i >= 0; i--) {
            processes.get(i).close();
        }
    }

    @Test
    void shouldSetAParameterOnTheHostItsNodeRunsOn() throws Exception {
        Finished run = runFor("--param", "Source:expression=42");
        assertThat(run.exit).as(run.output).isZero();
        // the flyer's Source now writes 42; the value reaches this process's stand-in of Level
        assertThat(run.output).as(run.output).containsPattern("main/Level\\s+[\\d,]+\\s+42\\.0000");

        Finished bad = runFor("--param", "Nobody:x=1");
        assertThat(bad.exit).as(bad.output).isEqualTo(2);
        assertThat(bad.output).contains("--param Nobody:x=1: ");
    }

    @Test
    void shouldSetADataOnItsHomeHost() throws Exception {
        Finished run = runFor("--set", "Goal=3.5");
        assertThat(run.exit).as(run.output).isZero();
        assertThat(run.output).as(run.output).containsPattern("main/Goal\\s+[\\d,]+\\s+3\\.5000");
    }

    @Test
    void shouldLoadAModuleOnItsHosts() throws Exception {
        try (Running run = start("--load", "Extra")) {
            assertThat(run.live.loadedModules()).as(run.output()).contains("Extra");
            assertThat(run.live.snapshot().module("Extra").nodes()).extracting(n -> n.name()).contains("Spare");
        }
    }

    @Test
    void shouldTraceEveryHostsOwnEventsEachLineNamingItsHost() throws Exception {
        Finished run = runFor("--as", "station", "--trace");
        assertThat(run.exit).as(run.output).isZero();
        assertThat(run.output).contains("--trace: every host's own events");
        // the flyer's own events, read from the flyer: its nodes named, its Source running and writing Level
        assertThat(run.output).as(run.output)
                .containsPattern("trace +[\\d.]+ flyer named +#\\d+ Data main/Level")
                .containsPattern("trace +[\\d.]+ flyer relation main/Source RUNNING")
                .containsPattern("trace +[\\d.]+ flyer value +main/Level = 1\\.0");
        // this process's host's own: the Operator; its stand-in of Level is the flyer's Data, traced there only
        assertThat(run.output)
                .containsPattern("trace +[\\d.]+ station relation main/Operator RUNNING")
                .doesNotContainPattern("trace +[\\d.]+ station named +#\\d+ Data main/Level")
                .doesNotContain("trace lines dropped");
        assertThat(run.output).containsPattern("trace so far: .*flyer [\\d,]+ lines \\(0 dropped\\)");
    }

    @Test
    void shouldSizeEveryHostsEngineForTheRunAndLeaveTheHostsOwnCountToARunWithoutWorkers() throws Exception {
        try (Running run = start("--as", "station", "--workers", "3")) {
            assertThat(run.output()).as(run.output()).containsPattern("worker threads for this run: .*flyer 3")
                    .containsPattern("worker threads for this run: .*station 3");
            // the flyer's engine really runs 3 worker threads for this run (its own count is 2)
            assertThat(awaitWorkerThreads(flyer.pid(), 3)).isEqualTo(3);
        }
        try (Running run = start("--as", "station")) {
            assertThat(run.output()).as(run.output()).containsPattern("worker threads for this run: .*flyer 2");
            assertThat(awaitWorkerThreads(flyer.pid(), 2)).isEqualTo(2);
        }
        Finished none = runFor("--workers", "0");
        assertThat(none.exit).isEqualTo(2);
        assertThat(none.output).contains("--workers 0: a network's engine runs 1 to 256 worker threads");
    }

    /**
     * The worker threads process {@code pid} runs, counted by their names in {@code /proc/PID/task/&#42;/comm} (Linux),
     * once they equal {@code expected} or after 10 s: a retired worker stops after its current poll.
     */
    private static int awaitWorkerThreads(long pid, int expected) throws Exception {
        long deadline = System.currentTimeMillis() + 10_000;
        int count;
        while ((count = workerThreadsOf(pid)) != expected && System.currentTimeMillis() < deadline) {
            Thread.sleep(50);
        }
        return count;
    }

    private static int workerThreadsOf(long pid) throws java.io.IOException {
        int count = 0;
        try (java.util.stream.Stream<Path> tasks = Files.list(Path.of("/proc", Long.toString(pid), "task"))) {
            for (Path task : (Iterable<Path>) tasks::iterator) {
                try {
                    if (Files.readString(task.resolve("comm")).startsWith("fdnet-worker-")) {
                        count++;
                    }
                } catch (java.nio.file.NoSuchFileException ended) {
                    // the thread ended while it was being listed
                }
            }
        }
        return count;
    }

    @Test
    void shouldTellToolsAttachedToTheRunWhereTheLoggersViewerIs() throws Exception {
        try (Running run = start("--logger-viewer", "127.0.0.1:5999");
             RemoteLiveNetwork attached = RemoteLiveNetwork.attach("options-test", naming)) {
            assertThat(attached.loggerViewerAddress()).as(run.output()).isEqualTo(Optional.of("127.0.0.1:5999"));
        }
    }

    @Test
    void shouldRefuseByNameWhatDoesNotApplyAcrossHosts() throws Exception {
        Finished sim = runFor("--sim", "flat");
        assertThat(sim.exit).isEqualTo(2);
        assertThat(sim.output).contains("--sim runs the network on this machine only");
        Finished port = runFor("--control-port", "4567");
        assertThat(port.exit).isEqualTo(2);
        assertThat(port.output).contains("--control-port: a distributed run registers its control object");
        Finished address = runFor("--control-host", "127.0.0.2");
        assertThat(address.exit).as(address.output).isEqualTo(2);
        assertThat(address.output).contains("--control-host: a distributed run registers its control object");
    }

    @Test
    void shouldRefuseToListenOffLoopbackWithoutTls() throws Exception {
        Finished open = runFor("--bind", "0.0.0.0");
        assertThat(open.exit).as(open.output).isEqualTo(2);
        assertThat(open.output).contains("0.0.0.0").contains("--tls");
    }

    @Test
    void shouldLoadThisHostsNodeClassesOnlyFromAllowedFolders() throws Exception {
        Path plugins = folder.resolve("plugins");
        compileEmit(plugins, "10");
        Path net = Files.createDirectories(folder.resolve("net"));
        Path plugged = Files.writeString(net.resolve("plugged.fdn"), PLUGGED.replace("PLUGINS", plugins.toString()));

        Finished refused = runFor(plugged);
        assertThat(refused.exit).as(refused.output).isEqualTo(1);
        assertThat(refused.output).contains("Emitter").contains("outside");

        Finished allowed = runFor(plugged, "--allow-path", plugins.toString());
        assertThat(allowed.exit).as(allowed.output).isZero();
        assertThat(allowed.output).containsPattern("main/Out\\s+[\\d,]+\\s+10\\.0000");
    }

    /** Source on the flyer; Emitter, a class of a folder outside the file's, on this process's host. */
    private static final String PLUGGED = """
            <?xml version="1.0" encoding="UTF-8"?>
            <cnet name="plugged">
                <dstructure><name>Level</name><host>flyer</host><path></path>
                    <class>org.fdnet.runtime.library.DoubleData</class></dstructure>
                <pstructure><name>Source</name><host>flyer</host><path></path>
                    <class>org.fdnet.runtime.library.Expression</class>
                    <param name="period" type="long">50</param><param name="expression">1</param></pstructure>
                <dstructure><name>Out</name><host>localhost</host><path></path>
                    <class>org.fdnet.runtime.library.DoubleData</class></dstructure>
                <pstructure><name>Emitter</name><host>localhost</host><path>PLUGINS</path>
                    <class>plugin.Emit</class></pstructure>
                <connection>
                    <write><data>Level</data><proc>Source</proc></write>
                    <read><data>Level</data><proc>Emitter</proc></read>
                    <write><data>Out</data><proc>Emitter</proc></write>
                </connection>
            </cnet>
            """;

    /** {@code plugin.Emit}: a Relation that writes {@code constant} whenever it fires, compiled into {@code folder}. */
    private static void compileEmit(Path folder, String constant) throws Exception {
        Path src = Files.createDirectories(folder.resolve("src/plugin")).resolve("Emit.java");
        Files.writeString(src, "package plugin;\n"
                + "public class Emit extends org.fdnet.runtime.Relation {\n"
                + "  protected void compute(org.fdnet.runtime.RelationContext c) {\n"
                + "    c.outputAll(org.fdnet.runtime.Value.of(" + constant + ".0));\n  }\n}\n");
        int rc = javax.tools.ToolProvider.getSystemJavaCompiler().run(null, null, null, "-d", folder.toString(),
                "-cp", System.getProperty("java.class.path"), src.toString());
        assertThat(rc).as("javac of plugin.Emit").isZero();
    }

    @Test
    void shouldPublishNoControlObjectWhenToldNot() throws Exception {
        try (Running run = start("--no-control")) {
            assertThat(run.output()).doesNotContain("control object");
            assertThatThrownBy(() -> RemoteLiveNetwork.attach("options-test", naming).close())
                    .as(run.output()).hasMessageContaining("options-test");
        }
    }

    private record Finished(int exit, String output) {
    }

    /** Runs the network for 2 s with {@code options} and returns how it ended. */
    private static Finished runFor(String... options) throws InterruptedException {
        return runFor(file, options);
    }

    /** Runs {@code network} for 2 s with {@code options} and returns how it ended. */
    private static Finished runFor(Path network, String... options) throws InterruptedException {
        StringWriter text = new StringWriter();
        PrintWriter out = new PrintWriter(text, true);
        int exit = networkRun(out, withBase(network, "--for", "2s", options)).run();
        return new Finished(exit, text.toString());
    }

    private static Running start(String... options) throws InterruptedException {
        StringWriter text = new StringWriter();
        NetworkRun run = networkRun(new PrintWriter(text, true), withBase("--for", "60s", options));
        Running running = new Running(run, text);
        running.thread.start();
        running.live = run.awaitRunning(60, TimeUnit.SECONDS);
        assertThat(running.live).as(text.toString()).isNotNull();
        return running;
    }

    private static NetworkRun networkRun(PrintWriter out, String[] args) {
        RunCommand command = CommandLine.populateCommand(new RunCommand(), args);
        return new NetworkRun(command.file, command.options, out, out, null);
    }

    private static String[] withBase(String forOption, String duration, String... options) {
        return withBase(file, forOption, duration, options);
    }

    private static String[] withBase(Path network, String forOption, String duration, String... options) {
        List<String> args = new ArrayList<>(List.of(network.toString(), "--naming", naming, forOption, duration));
        args.addAll(List.of(options));
        return args.toArray(String[]::new);
    }

    /** A run in the background, stopped (and awaited) on close. */
    private static final class Running implements AutoCloseable {
        final NetworkRun run;
        final StringWriter text;
        final Thread thread;
        LiveNetwork live;

        Running(NetworkRun run, StringWriter text) {
            this.run = run;
            this.text = text;
            this.thread = new Thread(() -> {
                try {
                    run.run();
                } catch (InterruptedException e) {
                    Thread.currentThread().interrupt();
                }
            }, "test-network-run");
        }

        String output() {
            return text.toString();
        }

        @Override
        public void close() throws InterruptedException {
            run.stop();
            thread.join(60_000);
        }
    }
}

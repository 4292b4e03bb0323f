package org.fdnet.apart;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.SQLException;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.function.Supplier;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.fdnet.corba.FdnetChildProcess;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.logger.store.EmbeddedDatabase;
import org.fdnet.tls.KeyMaker;
import org.fdnet.tls.TestKeys;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code networks/two-robots.fdn} with every process on an address of its own (the apart rig: a network namespace
 * each), all over mutual TLS with {@code fdnet keys} certificates, as on separate machines: the naming service and the
 * operator's {@code fdnet run} on one (as the two-hosts tutorial puts them), host flyer, host crawler, the logger and a
 * viewer on one each. Values cross the hosts, reach the logger's database and the viewer; every port each process
 * listens on lets a member in and refuses a client without a certificate and one with another network's; and no
 * process starts on such an address without TLS. Each namespace has its own ports, so the well-known ones are used.
 */
@Timeout(value = 420, unit = TimeUnit.SECONDS)
class ApartTlsRunTest {
    private static final String NETWORK = Path.of("../../networks/two-robots.fdn").toAbsolutePath().normalize().toString();
    private static final int NAMING_PORT = 2809;
    private static final int HOST_PORT = 7000;
    private static final int RECEIVER_PORT = 5555;
    private static final int SENDER_PORT = 5556;
    private static final long READY_MILLIS = 150_000;
    private static final Pattern COMMITTED = Pattern.compile("host (\\S+): logger: all ([\\d,]+) events of run ([0-9a-f-]{36}) committed");
    private static final Pattern LISTENER = Pattern.compile("LISTEN\\s+\\d+\\s+\\d+\\s+(\\S+):(\\d+)\\s");

    @TempDir
    Path folder;

    private ApartProcesses apart;
    private ApartRig rig;

    @AfterEach
    void cleanUp() {
        if (apart != null) {
            apart.close();
        }
    }

    @Test
    void shouldRunTwoRobotsOverTlsOnFiveAddressesAndRefuseEveryPortToStrangers() throws Exception {
        apart = ApartProcesses.create("fdnapartls", List.of("naming", "flyer", "crawler", "logger", "viewer"),
                folder.resolve("home"));
        rig = apart.rig();
        KeyMaker keys = new KeyMaker(folder.resolve("keys"));
        keys.make(List.of("naming", "flyer", "crawler", "operator", "logger", "viewer"));
        String naming = "corbaloc::" + address("naming") + ":" + NAMING_PORT + "/NameService";
        String logger = address("logger") + ":" + RECEIVER_PORT;
        Files.writeString(folder.resolve("logger.properties"), "database.embeddedDirectory=" + folder.resolve("pg")
                + "\nwriter.batchTimeoutMillis=200\n");

        FdnetChildProcess loggerProcess = inParallel(List.<Supplier<FdnetChildProcess>>of(
                () -> start("logger", "logger", List.of("logger", "--bind", address("logger"), "--receiver-port",
                        Integer.toString(RECEIVER_PORT), "--sender-port", Integer.toString(SENDER_PORT), "--config",
                        folder.resolve("logger.properties").toString(), "--tls", keys.store("logger").toString()),
                        "fdnet logger: cores -> "),
                () -> start("naming", "naming", List.of("naming", "--bind", address("naming"), "--port",
                        Integer.toString(NAMING_PORT), "--tls", keys.store("naming").toString()), "fdnet naming ready")))
                .get(0);
        List<FdnetChildProcess> hosts = inParallel(List.<Supplier<FdnetChildProcess>>of(
                () -> host("flyer", naming, keys), () -> host("crawler", naming, keys)));
        FdnetChildProcess run = start("run", "naming", List.of("run", NETWORK, "--bind", address("naming"), "--naming",
                naming, "--as", "operator", "--for", "60s", "--logger", logger, "--tls", keys.store("operator").toString()),
                "running on 3 hosts");

        // While it runs: every port on every address, the run's own included, and the viewer.
        List<String> ports = new ArrayList<>();
        for (String host : List.of("naming", "flyer", "crawler", "logger")) {
            List<String> listening = listeners(host);
            assertThat(listening).as("listeners on %s", host).isNotEmpty()
                    .allSatisfy(l -> assertThat(l).as("bound to the host's own address").startsWith(address(host) + ":"));
            String protocol = host.equals("logger") ? "/logger" : "/iiop";
            listening.forEach(l -> ports.add(host + "=" + l + protocol));
        }
        assertThat(ports).as("the naming service and the run (its host and control object) on the operator's address")
                .filteredOn(p -> p.startsWith("naming=")).hasSizeGreaterThanOrEqualTo(2);
        assertThat(ports).contains("logger=" + address("logger") + ":" + RECEIVER_PORT + "/logger",
                "logger=" + address("logger") + ":" + SENDER_PORT + "/logger",
                "flyer=" + address("flyer") + ":" + HOST_PORT + "/iiop", "crawler=" + address("crawler") + ":" + HOST_PORT
                        + "/iiop", "naming=" + address("naming") + ":" + NAMING_PORT + "/iiop");
        List<String> probeArgs = new ArrayList<>(List.of(keys.store("viewer").toString(), TestKeys.foreign().toString()));
        probeArgs.addAll(ports);
        List<List<String>> probes = inParallel(List.<Supplier<List<String>>>of(
                () -> java("viewer", PortRefusalProbe.class, probeArgs),
                () -> java("viewer", ViewerProbe.class, List.of(keys.store("viewer").toString(),
                        address("logger") + ":" + SENDER_PORT, "3", "Map", "Heading", "Certainty"))));
        List<String> knocks = probes.get(0).stream().filter(l -> l.startsWith("port ")).toList();
        assertThat(knocks).as(String.join("\n", probes.get(0))).hasSameSizeAs(ports)
                .allSatisfy(l -> assertThat(l).endsWith("member=accepted plain=refused foreign=refused"));
        List<String> viewer = probes.get(1);
        for (String data : List.of("Map", "Heading", "Certainty")) {
            assertThat(count(viewer, "viewer live " + data)).as("%s watched live:\n%s", data, viewer).isPositive();
            assertThat(count(viewer, "viewer history " + data)).as("%s in the history:\n%s", data, viewer).isPositive();
        }

        assertThat(run.awaitExit(180_000)).as(String.join("\n", run.output())).isZero();
        assertThat(run.output()).as("the crawler's decisions, from the flyer's map, reach the operator")
                .anyMatch(l -> l.startsWith("[operator]") && l.contains("main/Heading=")
                        && !l.endsWith("main/Certainty=0.0000"));
        for (FdnetChildProcess host : hosts) {
            host.stop(60_000);
        }
        loggerProcess.stop(60_000);
        List<Matcher> committed = run.output().stream().map(COMMITTED::matcher).filter(Matcher::find).toList();
        assertThat(committed).as(String.join("\n", run.output())).extracting(m -> m.group(1))
                .containsExactlyInAnyOrder("flyer", "crawler", "operator");

        try (EmbeddedDatabase database = EmbeddedDatabase.start(folder.resolve("pg"), 0)) {
            DatabaseTarget target = database.target();
            for (Matcher m : committed) {
                assertThat(LoggedRows.rowsOf(target, m.group(3))).as("rows of host %s", m.group(1))
                        .isEqualTo(Long.parseLong(m.group(2).replace(",", ""))).isPositive();
            }
            assertThat(LoggedRows.number(target, "SELECT count(*) FROM fdnet_run"))
                    .as("the three hosts' streams and nothing from the clients that were refused").isEqualTo(3);
            assertThat(valuesOf(target, "flyer", "Map")).isGreaterThan(5);
            assertThat(valuesOf(target, "crawler", "Heading")).isGreaterThan(5);
            assertThat(valuesOf(target, "crawler", "Certainty")).isGreaterThan(5);
        }
    }

    @Test
    void shouldRefuseToStartAnyServerOnItsOwnAddressWithoutTls() throws Exception {
        apart = ApartProcesses.create("fdnapartls", List.of("robot"), folder.resolve("home"));
        rig = apart.rig();
        String here = address("robot");
        String naming = "corbaloc::" + here + ":" + NAMING_PORT + "/NameService";
        List<List<String>> commands = List.of(
                List.of("naming", "--bind", here, "--port", Integer.toString(NAMING_PORT)),
                List.of("host", "--name", "robot", "--bind", here, "--naming", naming),
                List.of("run", NETWORK, "--bind", here, "--naming", naming),
                List.of("logger", "--bind", here, "--config", folder.resolve("none.properties").toString()));
        List<Supplier<FdnetChildProcess>> starts = new ArrayList<>();
        for (List<String> command : commands) {
            starts.add(() -> FdnetChildProcess.start(String.join(" ", command), rig.command("robot", List.of()),
                    apart.jvmOptions(), command, "without TLS", READY_MILLIS));
        }
        List<FdnetChildProcess> refused = inParallel(starts);
        for (int i = 0; i < commands.size(); i++) {
            FdnetChildProcess p = apart.add(refused.get(i));
            String label = String.join(" ", commands.get(i));
            assertThat(p.awaitExit(60_000)).as(label + "\n" + String.join("\n", p.output())).isNotZero();
            assertThat(String.join("\n", p.output())).as(label).contains("would listen on " + here)
                    .contains("without TLS").contains("--insecure");
        }
    }

    private FdnetChildProcess host(String name, String naming, KeyMaker keys) {
        return start("host " + name, name, List.of("host", "--name", name, "--bind", address(name), "--port",
                Integer.toString(HOST_PORT), "--naming", naming, "--tls", keys.store(name).toString()),
                "fdnet host " + name + " ready");
    }

    private FdnetChildProcess start(String label, String host, List<String> args, String ready) {
        return apart.start(label, host, args, ready, READY_MILLIS);
    }

    private String address(String host) {
        return apart.address(host);
    }

    /** Every TCP socket listening in {@code host}'s namespace on an address other hosts can reach, as ADDRESS:PORT. */
    private List<String> listeners(String host) throws IOException, InterruptedException {
        List<String> listening = new ArrayList<>();
        for (String line : output(rig.command(host, List.of("ss", "-ltnH")))) {
            Matcher m = LISTENER.matcher(line + " ");
            if (m.find()) {
                String address = m.group(1).replace("[::ffff:", "").replace("[", "").replace("]", "");
                if (!address.equals("127.0.0.1") && !address.equals("::1")) {
                    listening.add(address + ":" + m.group(2));
                }
            }
        }
        return listening;
    }

    /** Runs {@code main} of a probe in a JVM on {@code host}; its output. */
    private List<String> java(String host, Class<?> main, List<String> args) {
        List<String> argv = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Duser.home=" + folder.resolve("home"), "-cp", System.getProperty("java.class.path"), main.getName()));
        argv.addAll(args);
        try {
            return output(rig.command(host, argv));
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IllegalStateException(e);
        }
    }

    private static List<String> output(List<String> argv) throws IOException, InterruptedException {
        Process p = new ProcessBuilder(argv).redirectErrorStream(true).start();
        CompletableFuture<String> text = CompletableFuture.supplyAsync(() -> {
            try {
                return new String(p.getInputStream().readAllBytes(), StandardCharsets.UTF_8);
            } catch (IOException e) {
                return "";
            }
        });
        if (!p.waitFor(120, TimeUnit.SECONDS)) {
            p.destroyForcibly();
            throw new IllegalStateException(String.join(" ", argv) + " did not finish in 120 s");
        }
        return text.join().lines().toList();
    }

    private static <T> List<T> inParallel(List<Supplier<T>> tasks) {
        List<CompletableFuture<T>> running = new ArrayList<>();
        for (Supplier<T> task : tasks) {
            running.add(CompletableFuture.supplyAsync(task));
        }
        return running.stream().map(CompletableFuture::join).toList();
    }

    private static long count(List<String> lines, String prefix) {
        return lines.stream().filter(l -> l.startsWith(prefix + " ")).mapToLong(l -> Long.parseLong(l.substring(
                prefix.length() + 1).strip())).findFirst().orElse(0);
    }

    private static long valuesOf(DatabaseTarget db, String host, String data) throws SQLException {
        return LoggedRows.number(db, "SELECT count(*) FROM datavalue_log WHERE sourceid IN (SELECT n.sourceid"
                + " FROM fdnet_node n JOIN fdnet_run r USING (run_id) WHERE r.host = '" + host + "' AND n.module = 'main' AND n.node = '"
                + data + "')");
    }
}

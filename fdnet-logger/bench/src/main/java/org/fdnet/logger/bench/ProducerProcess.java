package org.fdnet.logger.bench;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/** A {@link BenchProducer} in its own JVM: started, told to go, and read for what its client accepted. */
final class ProducerProcess implements AutoCloseable {
    private final Process process;
    private final List<String> output = new ArrayList<>();
    private final Thread reader;

    /** What the producer's client accepted (values and names) and lost. */
    record Outcome(long accepted, long lost) {
    }

    ProducerProcess(int port, long events, long seconds, int nodes, long rate, String module, boolean waitForGo,
                    int memoryEvents) throws IOException {
        this(port, events, seconds, nodes, rate, module, waitForGo, memoryEvents, null);
    }

    /** As above; with {@code tlsStore} the producer connects over mutual TLS with that certificate. */
    ProducerProcess(int port, long events, long seconds, int nodes, long rate, String module, boolean waitForGo,
                    int memoryEvents, Path tlsStore) throws IOException {
        long heapMb = Math.max(1024, 512 + (long) memoryEvents * 400 / (1 << 20)); // ~400 bytes per event held
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Xmx" + heapMb + "m", "-Dorg.slf4j.simpleLogger.defaultLogLevel=warn"));
        cmd.addAll(extraJvmOptions(module));
        cmd.addAll(List.of("-cp", System.getProperty("java.class.path"), BenchProducer.class.getName(), "127.0.0.1",
                Integer.toString(port), Long.toString(events), Long.toString(seconds), Integer.toString(nodes),
                Long.toString(rate), module, waitForGo ? "go" : "now", Integer.toString(memoryEvents)));
        if (tlsStore != null) {
            cmd.add(tlsStore.toString());
        }
        process = new ProcessBuilder(cmd).redirectErrorStream(true).start();
        reader = new Thread(() -> {
            try (BufferedReader r = new BufferedReader(new InputStreamReader(process.getInputStream(), StandardCharsets.UTF_8))) {
                String line;
                while ((line = r.readLine()) != null) {
                    synchronized (output) {
                        output.add(line);
                        output.notifyAll();
                    }
                }
            } catch (IOException e) {
                synchronized (output) {
                    output.add("reader: " + e.getMessage());
                }
            }
        }, "bench-producer-output");
        reader.start();
    }

    /**
     * {@code FDNET_PRODUCER_JAVA_OPTS}, split on blanks: JVM options for the producer processes only (e.g. a
     * flight recording), as {@code FDNET_JAVA_OPTS} is for the logger's JVM. {@code %m} becomes the producer's
     * module ({@code sustained}, {@code latency}, {@code burst}), so each phase's recording gets its own file.
     */
    private static List<String> extraJvmOptions(String module) {
        String opts = System.getenv("FDNET_PRODUCER_JAVA_OPTS");
        List<String> out = new ArrayList<>();
        if (opts != null) {
            for (String o : opts.trim().split("\\s+")) {
                if (!o.isEmpty()) {
                    out.add(o.replace("%m", module));
                }
            }
        }
        return out;
    }

    boolean isAlive() {
        return process.isAlive();
    }

    /** Waits until the producer's names are committed (it printed {@code named}). */
    void awaitNamed(long timeoutMillis) throws InterruptedException {
        long deadline = System.currentTimeMillis() + timeoutMillis;
        synchronized (output) {
            while (!output.contains("named")) {
                long left = deadline - System.currentTimeMillis();
                if (left <= 0 || !process.isAlive()) {
                    throw new IllegalStateException("the producer did not name its nodes: " + String.join("\n", output));
                }
                output.wait(Math.min(left, 100));
            }
        }
    }

    void go() throws IOException {
        OutputStream in = process.getOutputStream();
        in.write('\n');
        in.flush();
    }

    /** Waits for the end and reads the last line; fails with the producer's output if it failed. */
    Outcome outcome() throws InterruptedException {
        process.waitFor();
        reader.join();
        synchronized (output) {
            for (String line : output) {
                if (line.startsWith("accepted ")) {
                    String[] p = line.split(" ");
                    if (process.exitValue() == 0) {
                        return new Outcome(Long.parseLong(p[1]), Long.parseLong(p[3]));
                    }
                }
            }
            throw new IllegalStateException("producer failed (exit " + process.exitValue() + "): " + String.join("\n", output));
        }
    }

    @Override
    public void close() throws InterruptedException {
        if (process.isAlive()) {
            process.destroy();
            if (!process.waitFor(10, TimeUnit.SECONDS)) {
                process.destroyForcibly();
            }
        }
    }
}

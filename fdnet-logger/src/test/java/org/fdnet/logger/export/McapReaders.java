package org.fdnet.logger.export;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.TimeUnit;

/**
 * The readers no one here wrote, as installed by {@code .ci/mcap-readers} into {@code target/mcap-readers} of the
 * repository: Python's {@code mcap} (and pandas) in a venv, {@code @mcap/core} under node. A missing reader fails the
 * test with one line saying how to install it — never a skip.
 */
public final class McapReaders {
    private final Path root;
    private final Path python;
    private final Path nodeModules;
    private final Path scripts;

    public McapReaders() {
        Path dir = Path.of("").toAbsolutePath();
        while (dir != null && !Files.exists(dir.resolve(".ci/mcap-readers"))) {
            dir = dir.getParent();
        }
        if (dir == null) {
            throw new IllegalStateException("no .ci/mcap-readers above " + Path.of("").toAbsolutePath());
        }
        root = dir;
        python = dir.resolve("target/mcap-readers/venv/bin/python");
        nodeModules = dir.resolve("target/mcap-readers/node/node_modules");
        scripts = dir.resolve("fdnet-logger/src/test/readers");
        if (!Files.isExecutable(python) || !Files.exists(nodeModules.resolve("@mcap/core/package.json"))) {
            throw new IllegalStateException("the MCAP readers (Python mcap, @mcap/core) are not installed in "
                    + dir.resolve("target/mcap-readers") + ": run .ci/mcap-readers (the fdnet-logger build runs it"
                    + " before its tests)");
        }
    }

    /** Python's reader on {@code mcap}: its one-line verdict. */
    public String python(Path mcap, Path expected, String... topics) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of(python.toString(), scripts.resolve("check_mcap.py").toString(), mcap.toString()));
        addChecks(cmd, expected, topics);
        return run(cmd);
    }

    /** @mcap/core's indexed reader on {@code mcap}: its one-line verdict. */
    public String typescript(Path mcap, Path expected, String... topics) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(List.of("node", scripts.resolve("check_mcap.cjs").toString(), mcap.toString()));
        addChecks(cmd, expected, topics);
        return run(cmd);
    }

    /** pandas: {@code rows columns} of a CSV file as {@code read_csv} loads it. */
    public String pandasShape(Path csv) throws IOException, InterruptedException {
        return run(List.of(python.toString(), "-c",
                "import sys, pandas; d = pandas.read_csv(sys.argv[1]); print(d.shape[0], d.shape[1])", csv.toString()));
    }

    private static void addChecks(List<String> cmd, Path expected, String... topics) {
        if (expected != null) {
            cmd.add("--expect");
            cmd.add(expected.toString());
        }
        for (String t : topics) {
            cmd.add("--topic");
            cmd.add(t);
        }
    }

    private String run(List<String> cmd) throws IOException, InterruptedException {
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(root.toFile()).redirectErrorStream(true);
        pb.environment().put("NODE_PATH", nodeModules.toString());
        Process p = pb.start();
        try {
            byte[] out = p.getInputStream().readAllBytes();
            if (!p.waitFor(120, TimeUnit.SECONDS)) {
                throw new IllegalStateException("reader did not finish in 120 s: " + cmd);
            }
            return new String(out, StandardCharsets.UTF_8).trim();
        } finally {
            p.destroyForcibly();
        }
    }
}

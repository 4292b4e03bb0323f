package org.fdnet.testing;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

/**
 * An X display for GUI tests: the one in {@code $DISPLAY}, or an Xvfb this test run started (and stops).
 * AWT reads {@code DISPLAY} from the process environment when it starts, which a running JVM cannot change,
 * so GUI scenarios run in a child JVM built by {@link #java}, with {@code DISPLAY} set.
 */
public final class RealDisplay {
    private final String name;
    private final boolean started;

    RealDisplay(String name, boolean started) {
        this.name = name;
        this.started = started;
    }

    /** {@code :99} and the like. */
    public String name() {
        return name;
    }

    /** True when this run started Xvfb for the tests (false: an existing display). */
    public boolean startedXvfb() {
        return started;
    }

    /** A child JVM running {@code main} on this display, with this JVM's class path. */
    public ProcessBuilder java(Class<?> main, String... args) {
        List<String> cmd = new ArrayList<>(List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(),
                "-Djava.awt.headless=false", "-cp", System.getProperty("java.class.path"), main.getName()));
        cmd.addAll(List.of(args));
        ProcessBuilder pb = new ProcessBuilder(cmd);
        pb.environment().put("DISPLAY", name);
        return pb;
    }
}

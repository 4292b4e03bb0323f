package org.fdnet.corba;

import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStream;
import java.io.InputStreamReader;
import java.io.UncheckedIOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;

/**
 * The fdnet commands whose JVM stops its JIT at C1, listed in {@code quick-jit-commands.txt} beside this class: the
 * one list both {@code bin/fdnet} and {@link FdnetChildProcess} read, so a child JVM runs as the launcher would run
 * the same command.
 */
public final class QuickJitCommands {
    /** The JVM option the listed commands run with. */
    public static final String OPTION = "-XX:TieredStopAtLevel=1";
    private static final String LIST = "quick-jit-commands.txt";
    private static final List<List<String>> COMMANDS = read();

    private QuickJitCommands() {
    }

    /** Whether {@code fdnet ARGS...} runs with its JIT stopped at C1: its first words are a listed command's. */
    public static boolean matches(List<String> fdnetArgs) {
        for (List<String> command : COMMANDS) {
            if (fdnetArgs.size() >= command.size() && fdnetArgs.subList(0, command.size()).equals(command)) {
                return true;
            }
        }
        return false;
    }

    private static List<List<String>> read() {
        List<List<String>> commands = new ArrayList<>();
        try (InputStream in = QuickJitCommands.class.getResourceAsStream(LIST)) {
            if (in == null) {
                throw new IllegalStateException(LIST + " is missing beside " + QuickJitCommands.class.getName());
            }
            BufferedReader lines = new BufferedReader(new InputStreamReader(in, StandardCharsets.UTF_8));
            for (String line = lines.readLine(); line != null; line = lines.readLine()) {
                String words = line.strip();
                if (!words.isEmpty() && !words.startsWith("#")) {
                    commands.add(Arrays.asList(words.split("\\s+")));
                }
            }
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read " + LIST, e);
        }
        return List.copyOf(commands);
    }
}

package org.fdnet.roq.sim;

import java.io.IOException;
import java.io.InputStream;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;

/**
 * Reads a course file: one {@code key = value} per line, {@code #} starts a comment. Keys: {@code name},
 * {@code terrain} (flat | slope | rubble), {@code length}, {@code width}, {@code cell}, {@code slope} (degrees),
 * {@code rubble.height}, {@code rubble.block}, {@code seed}, {@code start} (x y), and any number of
 * {@code fragile = x y sizeX sizeY height strength} (m, m, m, m, m, N), and any number (up to 32 in all) of
 * {@code push = start duration force direction} (s, s, N, degrees from +x, see {@link Push}) and
 * {@code break = time cell} (s, fragile cell index from 0 in file order, see {@link CellBreak}). Missing keys take {@link Course#flat()}'s
 * values. Every error names the file and line.
 *
 * <pre>
 * name    = rubble-crossing
 * terrain = rubble
 * seed    = 2004
 * start   = -1.5 0
 * fragile = 0.5 0.15 0.2 0.2 0.03 60
 * push    = 2.0 0.1 150 90      # at 2 s, for 0.1 s, 150 N to the left
 * break   = 3.5 0               # fragile cell 0 gives way at 3.5 s
 * </pre>
 */
public final class CourseLoader {
    /** Built-in courses, resources under {@code org/fdnet/roq/sim/courses/NAME.course}. */
    public static final List<String> BUILT_IN = List.of("flat", "slope", "rubble", "fragile", "crossing");

    private CourseLoader() {
    }

    /** A built-in course by name ({@link #BUILT_IN}) or else a course file's path. */
    public static Course resolve(String nameOrPath) throws CourseFormatException {
        if (BUILT_IN.contains(nameOrPath)) {
            String resource = "courses/" + nameOrPath + ".course";
            try (InputStream in = CourseLoader.class.getResourceAsStream(resource)) {
                if (in == null) {
                    throw new CourseFormatException("built-in course " + nameOrPath + ": resource " + resource
                            + " is missing from the roq-sim jar", null);
                }
                return parse(nameOrPath + ".course", new String(in.readAllBytes(), StandardCharsets.UTF_8));
            } catch (IOException e) {
                throw new CourseFormatException("built-in course " + nameOrPath + ": " + e.getMessage(), e);
            }
        }
        return load(Path.of(nameOrPath));
    }

    /**
     * The rubble course of the robot suites and the test kit's {@code rubble:SEED}: 4 m × 2 m, 6 cm blocks 0.25 m
     * wide placed by {@code seed}, 5 cm cells, RoQ starting 1.5 m before the middle.
     */
    public static Course rubble(long seed) throws CourseFormatException {
        return parse("rubble:" + seed, "name = rubble" + seed + "\nterrain = rubble\nlength = 4\nwidth = 2"
                + "\ncell = 0.05\nrubble.height = 0.06\nrubble.block = 0.25\nseed = " + seed + "\nstart = -1.5 0\n");
    }

    /**
     * The slope course of the robot suites and the test kit's {@code slope:DEGREES}: level up to x = 0, then
     * {@code degrees} up (negative: down) to x = 3; RoQ starts 0.4 m before the incline.
     */
    public static Course slope(double degrees) throws CourseFormatException {
        String d = degrees == Math.rint(degrees) ? Long.toString((long) degrees) : Double.toString(degrees);
        return parse("slope:" + d, "name = slope" + d + "\nterrain = slope\nslope = " + d
                + "\nlength = 6\nwidth = 2\ncell = 0.05\nstart = -0.4 0\n");
    }

    /** Reads the course file {@code file}. */
    public static Course load(Path file) throws CourseFormatException {
        String text;
        try {
            text = Files.readString(file, StandardCharsets.UTF_8);
        } catch (NoSuchFileException e) {
            throw new CourseFormatException(file + ": no such course file (built-in courses: "
                    + String.join(", ", BUILT_IN) + ")", e);
        } catch (IOException e) {
            throw new CourseFormatException(file + ": cannot read: " + e.getMessage(), e);
        }
        return parse(file.toString(), text);
    }

    /** Parses course text; {@code source} names it in error messages. */
    public static Course parse(String source, String text) throws CourseFormatException {
        Course d = Course.flat();
        String name = d.name();
        TerrainKind terrain = d.terrain();
        double length = d.length();
        double width = d.width();
        double cell = d.cellSize();
        double slope = d.slopeDegrees();
        double rubbleHeight = 0.06;
        double rubbleBlock = d.rubbleBlock();
        long seed = d.seed();
        double startX = d.startX();
        double startY = d.startY();
        List<FragileCell> cells = new ArrayList<>();
        List<Stimulus> stimuli = new ArrayList<>();
        String[] lines = text.split("\r?\n", -1);
        for (int n = 0; n < lines.length; n++) {
            String where = source + ":" + (n + 1) + ": ";
            String line = lines[n];
            int hash = line.indexOf('#');
            if (hash >= 0) {
                line = line.substring(0, hash);
            }
            line = line.strip();
            if (line.isEmpty()) {
                continue;
            }
            int eq = line.indexOf('=');
            if (eq < 0) {
                throw new CourseFormatException(where + "expected key = value, found '" + line + "'", null);
            }
            String key = line.substring(0, eq).strip();
            String value = line.substring(eq + 1).strip();
            try {
                switch (key) {
                    case "name" -> name = value;
                    case "terrain" -> terrain = terrain(value);
                    case "length" -> length = number(value);
                    case "width" -> width = number(value);
                    case "cell" -> cell = number(value);
                    case "slope" -> slope = number(value);
                    case "rubble.height" -> rubbleHeight = number(value);
                    case "rubble.block" -> rubbleBlock = number(value);
                    case "seed" -> seed = Long.parseLong(value);
                    case "start" -> {
                        double[] v = numbers(value, 2, "start = x y");
                        startX = v[0];
                        startY = v[1];
                    }
                    case "fragile" -> {
                        double[] v = numbers(value, 6, "fragile = x y sizeX sizeY height strength");
                        cells.add(new FragileCell(v[0], v[1], v[2], v[3], v[4], v[5]));
                    }
                    case "push" -> {
                        double[] v = numbers(value, 4, "push = start duration force direction");
                        stimuli.add(new Push(v[0], v[1], v[2], v[3]));
                    }
                    case "break" -> {
                        double[] v = numbers(value, 2, "break = time cell");
                        if (v[1] != Math.rint(v[1])) {
                            throw new IllegalArgumentException("break cell must be a whole index, was " + value);
                        }
                        stimuli.add(new CellBreak(v[0], (int) v[1]));
                    }
                    default -> throw new IllegalArgumentException("unknown key '" + key + "' (name, terrain, length, "
                            + "width, cell, slope, rubble.height, rubble.block, seed, start, fragile, push, break)");
                }
            } catch (NumberFormatException e) {
                throw new CourseFormatException(where + key + ": not a number: '" + value + "'", e);
            } catch (IllegalArgumentException e) {
                throw new CourseFormatException(where + e.getMessage(), e);
            }
        }
        if (terrain != TerrainKind.RUBBLE) {
            rubbleHeight = 0;
        }
        try {
            return new Course(name, terrain, length, width, cell, slope, rubbleHeight, rubbleBlock, seed,
                    startX, startY, cells, stimuli);
        } catch (IllegalArgumentException e) {
            throw new CourseFormatException(source + ": " + e.getMessage(), e);
        }
    }

    private static TerrainKind terrain(String value) {
        try {
            return TerrainKind.valueOf(value.toUpperCase(Locale.ROOT));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("unknown terrain '" + value + "' (flat, slope or rubble)", e);
        }
    }

    private static double number(String value) {
        double v = Double.parseDouble(value);
        if (!Double.isFinite(v)) {
            throw new NumberFormatException(value);
        }
        return v;
    }

    private static double[] numbers(String value, int count, String form) {
        String[] parts = value.split("\\s+");
        if (parts.length != count) {
            throw new IllegalArgumentException("expected " + form + ", found '" + value + "'");
        }
        double[] v = new double[count];
        for (int i = 0; i < count; i++) {
            v[i] = number(parts[i]);
        }
        return v;
    }
}

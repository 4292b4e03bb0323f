package org.fdnet.roq.sim;

import java.util.List;

/**
 * A course for the RoQ: the terrain (a heightfield, see {@link Heightfield#of(Course)}), where the robot starts,
 * and the {@link FragileCell}s. Read from a small text file by {@link CourseLoader}; the built-in courses are
 * {@link #flat()}, {@link #slope(double)} and {@link #rubble(long)}.
 *
 * @param name          shown in logs and the view
 * @param terrain       the kind of ground
 * @param length        extent along x, m (the course spans −length/2 … +length/2)
 * @param width         extent along y, m
 * @param cellSize      heightfield resolution, m
 * @param slopeDegrees  {@link TerrainKind#SLOPE}: incline after x = 0, degrees (negative: falling along +x)
 * @param rubbleHeight  {@link TerrainKind#RUBBLE}: tallest block, m
 * @param rubbleBlock   {@link TerrainKind#RUBBLE}: block edge, m
 * @param seed          {@link TerrainKind#RUBBLE}: seed of the block heights (same seed, same course)
 * @param startX        where the robot's body centre starts, m
 * @param startY        m
 * @param fragileCells  blocks that break under load
 * @param stimuli       pushes and cell breaks applied at set times ({@link Stimulus}); at most
 *                      {@link SharedBlockLayout#MAX_STIMULI}
 */
public record Course(String name, TerrainKind terrain, double length, double width, double cellSize,
                     double slopeDegrees, double rubbleHeight, double rubbleBlock, long seed,
                     double startX, double startY, List<FragileCell> fragileCells, List<Stimulus> stimuli) {
    /** Most fragile cells a course may have (the snapshot's broken-cell bit mask). */
    public static final int MAX_FRAGILE_CELLS = 256;

    /** Checks the figures; the message names the bad one. */
    public Course {
        require(name != null && !name.isBlank(), "course name must not be empty");
        require(terrain != null, "course terrain must be given");
        require(length >= 1 && length <= 50, "course length must be 1..50 m, was " + length);
        require(width >= 1 && width <= 50, "course width must be 1..50 m, was " + width);
        require(cellSize >= 0.01 && cellSize <= 0.5, "course cell must be 0.01..0.5 m, was " + cellSize);
        require(length / cellSize <= 1000 && width / cellSize <= 1000,
                "course has too many cells (at most 1000 along a side): " + length + " x " + width + " m at " + cellSize);
        require(slopeDegrees >= -30 && slopeDegrees <= 30, "course slope must be -30..30 degrees, was " + slopeDegrees);
        require(rubbleHeight >= 0 && rubbleHeight <= 0.3, "rubble.height must be 0..0.3 m, was " + rubbleHeight);
        require(rubbleBlock >= cellSize, "rubble.block must be at least the cell (" + cellSize + " m), was " + rubbleBlock);
        require(Math.abs(startX) < length / 2 && Math.abs(startY) < width / 2,
                "start " + startX + " " + startY + " lies outside the course");
        fragileCells = List.copyOf(fragileCells);
        require(fragileCells.size() <= MAX_FRAGILE_CELLS,
                "a course has at most " + MAX_FRAGILE_CELLS + " fragile cells, this one " + fragileCells.size());
        for (int i = 0; i < fragileCells.size(); i++) {
            FragileCell c = fragileCells.get(i);
            require(Math.abs(c.x()) + c.sizeX() / 2 <= length / 2 && Math.abs(c.y()) + c.sizeY() / 2 <= width / 2,
                    "fragile cell " + i + " at " + c.x() + " " + c.y() + " lies outside the course");
        }
        stimuli = List.copyOf(stimuli);
        require(stimuli.size() <= SharedBlockLayout.MAX_STIMULI,
                "a course has at most " + SharedBlockLayout.MAX_STIMULI + " pushes and breaks, this one " + stimuli.size());
        for (Stimulus x : stimuli) {
            if (x instanceof CellBreak b) {
                require(b.cell() < fragileCells.size(), "break names fragile cell " + b.cell() + " but the course has "
                        + fragileCells.size() + " (numbered from 0)");
            }
        }
    }

    /** A course without pushes or breaks. */
    public Course(String name, TerrainKind terrain, double length, double width, double cellSize, double slopeDegrees,
                  double rubbleHeight, double rubbleBlock, long seed, double startX, double startY,
                  List<FragileCell> fragileCells) {
        this(name, terrain, length, width, cellSize, slopeDegrees, rubbleHeight, rubbleBlock, seed, startX, startY,
                fragileCells, List.of());
    }

    private static void require(boolean ok, String message) {
        if (!ok) {
            throw new IllegalArgumentException(message);
        }
    }

    /** Flat ground, 4 × 2 m, robot at the centre, no fragile cells. */
    public static Course flat() {
        return new Course("flat", TerrainKind.FLAT, 4, 2, 0.05, 0, 0, 0.25, 0, 0, 0, List.of());
    }

    /** Flat, then a slope of {@code degrees} from x = 0; the robot starts 1 m before it. */
    public static Course slope(double degrees) {
        return new Course("slope", TerrainKind.SLOPE, 4, 2, 0.05, degrees, 0, 0.25, 0, -1, 0, List.of());
    }

    /** Rubble up to 6 cm in 25 cm blocks from {@code seed}; the robot starts on a clear patch at x = −1.5 m. */
    public static Course rubble(long seed) {
        return new Course("rubble", TerrainKind.RUBBLE, 4, 2, 0.05, 0, 0.06, 0.25, seed, -1.5, 0, List.of());
    }

    /** This course with other fragile cells. */
    public Course withFragileCells(List<FragileCell> cells) {
        return new Course(name, terrain, length, width, cellSize, slopeDegrees, rubbleHeight, rubbleBlock, seed,
                startX, startY, cells, stimuli);
    }

    /** This course with the robot starting elsewhere. */
    public Course withStart(double x, double y) {
        return new Course(name, terrain, length, width, cellSize, slopeDegrees, rubbleHeight, rubbleBlock, seed,
                x, y, fragileCells, stimuli);
    }

    /** This course with other pushes and cell breaks. */
    public Course withStimuli(List<Stimulus> list) {
        return new Course(name, terrain, length, width, cellSize, slopeDegrees, rubbleHeight, rubbleBlock, seed,
                startX, startY, fragileCells, list);
    }
}

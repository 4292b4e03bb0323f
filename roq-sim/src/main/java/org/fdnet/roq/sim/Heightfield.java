package org.fdnet.roq.sim;

import java.util.List;
import java.util.SplittableRandom;

/**
 * The terrain's heights on a regular grid: {@code rows} along y, {@code cols} along x, row-major from (−length/2,
 * −width/2). What MuJoCo's heightfield is filled with, and what the view draws. Each fragile cell sits in a pit of
 * its own height carved into the terrain, its top flush with the ground around ({@link #cellTop(int)}): when it
 * breaks, the pit opens.
 */
public final class Heightfield {
    /** Clear ground kept around the start of a rubble course, m (the robot is set down on level ground). */
    public static final double START_CLEARANCE = 0.6;

    private final int rows;
    private final int cols;
    private final double length;
    private final double width;
    private final float[] heights;
    private final double[] cellTops;
    private final List<FragileCell> cells;

    private Heightfield(int rows, int cols, double length, double width, float[] heights, double[] cellTops,
                        List<FragileCell> cells) {
        this.cells = cells;
        this.rows = rows;
        this.cols = cols;
        this.length = length;
        this.width = width;
        this.heights = heights;
        this.cellTops = cellTops;
    }

    /** Builds the terrain of {@code course} (deterministic: same course, same heights). */
    public static Heightfield of(Course course) {
        int cols = (int) Math.round(course.length() / course.cellSize()) + 1;
        int rows = (int) Math.round(course.width() / course.cellSize()) + 1;
        float[] h = new float[rows * cols];
        double tan = Math.tan(Math.toRadians(course.slopeDegrees()));
        int blocksX = (int) Math.ceil(course.length() / course.rubbleBlock());
        int blocksY = (int) Math.ceil(course.width() / course.rubbleBlock());
        double[] block = new double[blocksX * blocksY];
        SplittableRandom random = new SplittableRandom(course.seed());
        for (int i = 0; i < block.length; i++) {
            block[i] = random.nextDouble() * course.rubbleHeight();
        }
        for (int r = 0; r < rows; r++) {
            for (int c = 0; c < cols; c++) {
                double x = -course.length() / 2 + c * course.length() / (cols - 1);
                double y = -course.width() / 2 + r * course.width() / (rows - 1);
                double z = switch (course.terrain()) {
                    case FLAT -> 0;
                    // rising along +x after x = 0; a negative slope falls there instead, from a level part raised
                    // so that the course's far end is at 0 (heights are never negative)
                    case SLOPE -> (Math.max(0, x) - (tan < 0 ? course.length() / 2 : 0)) * tan;
                    case RUBBLE -> {
                        if (Math.hypot(x - course.startX(), y - course.startY()) < START_CLEARANCE) {
                            yield 0;
                        }
                        int bx = Math.min(blocksX - 1, (int) ((x + course.length() / 2) / course.rubbleBlock()));
                        int by = Math.min(blocksY - 1, (int) ((y + course.width() / 2) / course.rubbleBlock()));
                        yield block[by * blocksX + bx];
                    }
                };
                h[r * cols + c] = (float) Math.max(0, z);
            }
        }
        Heightfield ground = new Heightfield(rows, cols, course.length(), course.width(), h, new double[0], List.of());
        double[] tops = new double[course.fragileCells().size()];
        for (int i = 0; i < tops.length; i++) {
            tops[i] = ground.heightAt(course.fragileCells().get(i).x(), course.fragileCells().get(i).y());
        }
        float[] carved = h.clone();
        for (int i = 0; i < tops.length; i++) {
            FragileCell cell = course.fragileCells().get(i);
            for (int r = 0; r < rows; r++) {
                for (int c = 0; c < cols; c++) {
                    if (cell.contains(ground.x(c), ground.y(r))) {
                        carved[r * cols + c] = (float) Math.min(carved[r * cols + c], tops[i] - cell.height());
                    }
                }
            }
        }
        return new Heightfield(rows, cols, course.length(), course.width(), carved, tops, course.fragileCells());
    }

    /** The course's fragile cells, in their order (the snapshot's broken-cell indices). */
    public List<FragileCell> fragileCells() {
        return cells;
    }

    /** The top of fragile cell {@code index}: the terrain's height at its centre before its pit was carved, m. */
    public double cellTop(int index) {
        return cellTops[index];
    }

    /** Grid points along y. */
    public int rows() {
        return rows;
    }

    /** Grid points along x. */
    public int cols() {
        return cols;
    }

    /** Extent along x, m. */
    public double length() {
        return length;
    }

    /** Extent along y, m. */
    public double width() {
        return width;
    }

    /** Height at grid point (row, col), m. */
    public double height(int row, int col) {
        return heights[row * cols + col];
    }

    /** x of column {@code col}, m. */
    public double x(int col) {
        return -length / 2 + col * length / (cols - 1);
    }

    /** y of row {@code row}, m. */
    public double y(int row) {
        return -width / 2 + row * width / (rows - 1);
    }

    /** The tallest point, m. */
    public double maxHeight() {
        double m = heights[0];
        for (float v : heights) {
            m = Math.max(m, v);
        }
        return m;
    }

    /** The lowest point (a fragile cell's pit may go below 0), m. */
    public double minHeight() {
        double m = heights[0];
        for (float v : heights) {
            m = Math.min(m, v);
        }
        return m;
    }

    /** The heights scaled to 0..1 over {@link #minHeight()}..{@link #maxHeight()}: MuJoCo's heightfield data. */
    float[] normalised() {
        double min = minHeight();
        double range = Math.max(MIN_ELEVATION_RANGE, maxHeight() - min);
        float[] n = new float[heights.length];
        for (int i = 0; i < n.length; i++) {
            n[i] = (float) ((heights[i] - min) / range);
        }
        return n;
    }

    /** The least elevation range given to MuJoCo (a flat course still needs a non-zero one), m. */
    static final double MIN_ELEVATION_RANGE = 0.01;

    /** MuJoCo's elevation range for this terrain, m. */
    double elevationRange() {
        return Math.max(MIN_ELEVATION_RANGE, maxHeight() - minHeight());
    }

    /**
     * Height at (x, y), bilinear between grid points, m; 0 off the grid. MuJoCo triangulates each cell instead: the
     * two agree at grid points and along cell edges and differ inside a cell by at most its height step.
     */
    public double heightAt(double x, double y) {
        double fc = (x + length / 2) / length * (cols - 1);
        double fr = (y + width / 2) / width * (rows - 1);
        if (fc < 0 || fr < 0 || fc > cols - 1 || fr > rows - 1) {
            return 0;
        }
        int c0 = Math.min(cols - 2, (int) fc);
        int r0 = Math.min(rows - 2, (int) fr);
        double tc = fc - c0;
        double tr = fr - r0;
        double a = height(r0, c0) * (1 - tc) + height(r0, c0 + 1) * tc;
        double b = height(r0 + 1, c0) * (1 - tc) + height(r0 + 1, c0 + 1) * tc;
        return a * (1 - tr) + b * tr;
    }

    /** A copy of the heights, row-major. */
    public float[] toArray() {
        return heights.clone();
    }
}

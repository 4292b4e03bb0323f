package org.fdnet.roq.node;

/**
 * The swing trajectory of one foot, in the gait's ground frame (x, y on the ground, z the foot's height in the body
 * frame): it first <b>rises</b> straight up (at most {@code clearance}) until its sole has left the ground and it is
 * {@code clearance}/3 up (a
 * foot that went forward while still bearing load was driven into whatever stood before it), then <b>moves</b> over
 * to above its foothold, {@code clearance} above the higher of the two grounds (or of the ground it is told to pass
 * over), and then <b>descends</b> at
 * {@code descent} m/s until its sole finds the ground — or has gone {@code depth} m below where the ground was
 * expected without finding it (no footing).
 */
final class SwingPath {
    enum Stage { RISE, MOVE, DESCEND, DOWN, NO_FOOTING }

    private Stage stage = Stage.DOWN;
    private double fromX;
    private double fromY;
    private double fromZ;
    private double toX;
    private double toY;
    private double groundZ;
    private double overZ;
    private double clearance;
    private double moveTime;
    private double t;
    private double x;
    private double y;
    private double z;
    private final double riseSpeed;
    private final double descent;
    private final double depth;
    private final double speed;

    /** A path rising at {@code riseSpeed} m/s, moving at {@code speed} m/s, descending at {@code descent} m/s. */
    SwingPath(double riseSpeed, double speed, double descent, double depth) {
        this.riseSpeed = riseSpeed;
        this.speed = speed;
        this.descent = descent;
        this.depth = depth;
    }

    /**
     * Starts a swing from (x, y, z) to the foothold (toX, toY) whose ground is expected at height {@code groundZ}.
     */
    void start(double x, double y, double z, double toX, double toY, double groundZ, double clearance) {
        start(x, y, z, toX, toY, groundZ, groundZ, clearance);
    }

    /**
     * Starts a swing as {@link #start(double, double, double, double, double, double, double)} does that moves over
     * at {@code clearance} above {@code overZ} when that is higher than the expected ground.
     */
    void start(double x, double y, double z, double toX, double toY, double groundZ, double overZ, double clearance) {
        this.overZ = Math.max(groundZ, overZ);
        this.fromX = x;
        this.fromY = y;
        this.fromZ = z;
        this.x = x;
        this.y = y;
        this.z = z;
        this.toX = toX;
        this.toY = toY;
        this.groundZ = groundZ;
        this.clearance = clearance;
        this.moveTime = Math.max(0.25, Math.hypot(toX - x, toY - y) / speed);
        this.t = 0;
        stage = Stage.RISE;
    }

    /** Advances by {@code dt} s, told whether the sole is off the ground and whether it touches it. */
    Stage advance(double dt, boolean liftedOff, boolean touches) {
        switch (stage) {
            case RISE -> {
                z = Math.min(fromZ + clearance, z + riseSpeed * dt);
                if (liftedOff && z - fromZ >= clearance / 3) {
                    stage = Stage.MOVE;
                    fromZ = z;
                    t = 0;
                }
            }
            case MOVE -> {
                t += dt;
                double u = Math.min(1, t / moveTime);
                double w = u * u * (3 - 2 * u);
                x = fromX + (toX - fromX) * w;
                y = fromY + (toY - fromY) * w;
                double top = Math.max(fromZ, overZ + clearance);
                z += Math.max(-riseSpeed * dt, Math.min(riseSpeed * dt, top - z)) ;
                if (u >= 1) {
                    stage = Stage.DESCEND;
                }
            }
            case DESCEND -> {
                if (touches) {
                    stage = Stage.DOWN;
                } else if (z < groundZ - depth) {
                    stage = Stage.NO_FOOTING;
                } else {
                    z -= descent * dt * (z > groundZ + 0.02 ? 3 : 1);
                }
            }
            default -> {
            }
        }
        return stage;
    }

    Stage stage() {
        return stage;
    }

    double x() {
        return x;
    }

    double y() {
        return y;
    }

    double z() {
        return z;
    }
}

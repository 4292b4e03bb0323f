package org.fdnet.roq.sim;

import java.io.IOException;
import java.io.UncheckedIOException;
import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.file.Files;
import java.nio.file.Path;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The simulated RoQ: MuJoCo physics and 12 servos driven by a C joint loop, reached through one shared direct
 * buffer ({@link SharedBlockLayout}).
 *
 * <pre>
 *  send(JointCommand) ──▶ command slot ──▶ C tick: servos ─▶ mj_step ─▶ sensors ─▶ seqlock snapshot ──▶ read(SensorSnapshot)
 *                                          (1 kHz thread in REAL_TIME; step(n) on the caller's thread in STEPPED)
 * </pre>
 *
 * <p>{@link #read} and {@link #send} make no JNI call and do not allocate; they may be called from any thread
 * ({@code send} calls are serialised). {@link #step}, {@link #close} and the ground-truth checks call into C.
 * Close it: it owns native memory and, in real-time mode, a thread.
 */
public final class RoqSimulator implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(RoqSimulator.class);
    private static final VarHandle LONGS = MethodHandles.byteBufferViewVarHandle(long[].class, ByteOrder.nativeOrder());

    private final Course course;
    private final Heightfield heightfield;
    private final SimOptions options;
    private final ByteBuffer block;
    private final Object commandLock = new Object();
    private final StimulusTable stimuli;
    private long handle;
    private volatile long lastReadTick;

    private RoqSimulator(Course course, Heightfield heightfield, SimOptions options, ByteBuffer block, long handle) {
        this.course = course;
        this.heightfield = heightfield;
        this.options = options;
        this.block = block;
        this.handle = handle;
        this.stimuli = new StimulusTable(block, course.fragileCells().size());
    }

    /** Opens {@code course} in {@code mode} with the default options ({@link SimOptions#of}). */
    public static RoqSimulator open(Course course, SimMode mode) {
        return open(course, SimOptions.of(mode));
    }

    /**
     * Opens {@code course}: loads the native library (see {@link RoqNativeLibrary}), builds the model, sets the
     * robot down at the course's start in the standing pose and, in {@link SimMode#REAL_TIME}, starts the loop.
     *
     * @throws NativeLibraryUnavailableException when the native side is missing (the message says what to install)
     * @throws IllegalStateException             when MuJoCo refuses the model (its message is kept)
     */
    public static RoqSimulator open(Course course, SimOptions options) {
        RoqNativeLibrary.ensureLoaded();
        Heightfield terrain = Heightfield.of(course);
        String mjcf = MjcfWriter.write(course, terrain, options.dropHeight());
        ByteBuffer block = ByteBuffer.allocateDirect(SharedBlockLayout.BLOCK_SIZE + 64).alignedSlice(64)
                .order(ByteOrder.nativeOrder());
        block.limit(SharedBlockLayout.BLOCK_SIZE);
        block = block.slice().order(ByteOrder.nativeOrder());
        long handle;
        Path file = null;
        try {
            file = Files.createTempFile("roq-", ".xml");
            Files.writeString(file, mjcf);
            handle = RoqNative.open(file.toString(), terrain.normalised(),
                    NativeParameters.fragileFigures(course.fragileCells()), NativeParameters.of(options), block);
        } catch (IOException e) {
            throw new UncheckedIOException("roq-sim: cannot write the model file " + file, e);
        } finally {
            deleteQuietly(file);
        }
        RoqSimulator sim = new RoqSimulator(course, terrain, options, block, handle);
        for (Stimulus x : course.stimuli()) {
            sim.stimulate(x);
        }
        if (options.mode() == SimMode.REAL_TIME) {
            String warnings;
            try {
                warnings = RoqNative.start(handle, options.priority());
            } catch (IllegalStateException e) {
                sim.close();
                throw e;
            }
            if (!warnings.isEmpty()) {
                LOG.warn("roq-sim real-time loop runs without {} (run as root for real-time figures)", warnings);
            }
        }
        LOG.debug("roq-sim opened course {} in {} mode", course.name(), options.mode());
        return sim;
    }

    private static void deleteQuietly(Path file) {
        if (file == null) {
            return;
        }
        try {
            Files.deleteIfExists(file);
        } catch (IOException e) {
            LOG.warn("roq-sim: cannot delete the temporary model file {}: {}", file, e.getMessage());
        }
    }

    /** The course this simulator runs. */
    public Course course() {
        return course;
    }

    /** The course's terrain, as MuJoCo has it. */
    public Heightfield heightfield() {
        return heightfield;
    }

    /** How this simulator advances time. */
    public SimMode mode() {
        return options.mode();
    }

    /**
     * Stepped mode: runs {@code ticks} ticks (1 ms each) now, on this thread, with no wall clock.
     *
     * @throws IllegalStateException in real-time mode or after {@link #close()}
     */
    public synchronized void step(int ticks) {
        if (options.mode() != SimMode.STEPPED) {
            throw new IllegalStateException("step(n) is for STEPPED mode; this simulator runs in real time");
        }
        if (ticks < 0) {
            throw new IllegalArgumentException("ticks must be >= 0, was " + ticks);
        }
        RoqNative.step(liveHandle(), ticks);
    }

    /**
     * Copies the latest consistent snapshot into {@code into}: no JNI, no allocation (a seqlock read that retries
     * while the loop is writing). Returns its tick. Works after close (the last snapshot stays readable).
     */
    public long read(SensorSnapshot into) {
        while (true) {
            long before = (long) LONGS.getAcquire(block, SharedBlockLayout.SNAPSHOT_SEQ);
            if ((before & 1) != 0) {
                Thread.onSpinWait();
                continue;
            }
            into.copyFrom(block);
            VarHandle.acquireFence();
            long after = (long) LONGS.getOpaque(block, SharedBlockLayout.SNAPSHOT_SEQ);
            if (before == after) {
                lastReadTick = into.tick();
                return into.tick();
            }
        }
    }

    /**
     * Puts {@code command} into the command slot; the loop takes it at its next tick. No JNI, no allocation.
     * The command is stamped with {@link JointCommand#basedOnTick()} or, when that is −1, the tick of the last
     * snapshot {@link #read}; the loop ignores it (counted stale) when that is over
     * {@link SharedBlockLayout#STALE_TICKS} ticks old.
     */
    public void send(JointCommand command) {
        long issued = command.basedOnTick() >= 0 ? command.basedOnTick() : lastReadTick;
        synchronized (commandLock) {
            long seq = (long) LONGS.getOpaque(block, SharedBlockLayout.COMMAND_SEQ);
            LONGS.setVolatile(block, SharedBlockLayout.COMMAND_SEQ, seq + 1);
            VarHandle.releaseFence();
            block.putLong(SharedBlockLayout.C_ISSUED_TICK, issued);
            for (int j = 0; j < RoqGeometry.JOINTS; j++) {
                block.putDouble(SharedBlockLayout.C_TARGETS + 8 * j, command.target(j));
            }
            for (int i = 0; i < RoqGeometry.LEGS; i++) {
                block.putDouble(SharedBlockLayout.C_WHEEL_SPEED + 8 * i, command.wheelSpeed(i));
            }
            block.putLong(SharedBlockLayout.C_FLAGS, command.wheelsEnabled() ? SharedBlockLayout.FLAG_WHEELS : 0);
            block.putLong(SharedBlockLayout.C_SOURCE_TICK, command.sourceTick() < 0 ? issued : command.sourceTick());
            LONGS.setRelease(block, SharedBlockLayout.COMMAND_SEQ, seq + 2);
        }
    }

    /**
     * Copies the applied commands numbered (from 0) {@code from} … (at most the {@link SharedBlockLayout#APPLIED_RING}
     * newest) into {@code appliedTicks} / {@code sourceTicks}: the tick each was applied at (it shows in snapshot
     * tick + 1) and the newest snapshot it was computed from (0: none). Returns how many commands have been applied
     * in all; entries older than the ring are lost (fewer copied than asked). A seqlock read, no JNI.
     *
     * @return the number of commands applied so far, n: commands max({@code from}, n − 64) … n − 1 were copied, in
     *         order, from index 0
     */
    public long appliedCommands(long from, long[] appliedTicks, long[] sourceTicks) {
        while (true) {
            long before = (long) LONGS.getAcquire(block, SharedBlockLayout.SNAPSHOT_SEQ);
            if ((before & 1) != 0) {
                Thread.onSpinWait();
                continue;
            }
            long count = block.getLong(SharedBlockLayout.T_COMMANDS_APPLIED);
            long first = Math.max(from, count - SharedBlockLayout.APPLIED_RING);
            for (long n = first; n < count && n - first < appliedTicks.length; n++) {
                int at = SharedBlockLayout.A_RING + SharedBlockLayout.A_ENTRY_SIZE * (int) (n % SharedBlockLayout.APPLIED_RING);
                appliedTicks[(int) (n - first)] = block.getLong(at);
                sourceTicks[(int) (n - first)] = block.getLong(at + 8);
            }
            VarHandle.acquireFence();
            if (before == (long) LONGS.getOpaque(block, SharedBlockLayout.SNAPSHOT_SEQ)) {
                return count;
            }
        }
    }

    /**
     * Adds a push or cell break; the loop applies it from its {@link Stimulus#firstTick()} (a push already under way
     * acts for what is left of it). Stimuli that have ended by the last {@link #read} snapshot are dropped to make
     * room; at most {@link SharedBlockLayout#MAX_STIMULI} may be pending. No JNI.
     *
     * @throws IllegalArgumentException when a {@link CellBreak} names a cell the course lacks, or the table is full
     */
    public void stimulate(Stimulus stimulus) {
        stimuli.add(stimulus, lastReadTick);
    }

    /** Copies the loop's statistics into {@code into} (a seqlock read, like {@link #read}). Returns {@code into}. */
    public LoopStatistics statistics(LoopStatistics into) {
        while (true) {
            long before = (long) LONGS.getAcquire(block, SharedBlockLayout.SNAPSHOT_SEQ);
            if ((before & 1) != 0) {
                Thread.onSpinWait();
                continue;
            }
            into.copyFrom(block);
            VarHandle.acquireFence();
            if (before == (long) LONGS.getOpaque(block, SharedBlockLayout.SNAPSHOT_SEQ)) {
                return into;
            }
        }
    }

    /**
     * A hash of the whole physical state (time, positions, velocities, accelerations, fragile cells): two stepped
     * runs of the same course and commands give the same hash. Stepped mode only.
     */
    public synchronized long stateHash() {
        return RoqNative.stateHash(steppedHandle("stateHash()"));
    }

    /**
     * Nanoseconds a bare {@code mj_step} loop of this model takes for {@code ticks} steps from the current state
     * (the bench baseline). Stepped mode only.
     */
    public synchronized long bareStepNanos(int ticks) {
        return RoqNative.bareStepNanos(steppedHandle("bareStepNanos()"), ticks);
    }

    /** A figure of the loaded MuJoCo model ({@link RoqNative#modelValue}); for checks against RoqGeometry. */
    synchronized double modelValue(int what, String name) {
        return RoqNative.modelValue(steppedHandle("a model probe"), what, name);
    }

    /** The handle, for calls that read MuJoCo's state: only safe while no loop thread writes it. */
    private long steppedHandle(String what) {
        if (options.mode() != SimMode.STEPPED) {
            throw new IllegalStateException(what + " reads the simulation's state and is for STEPPED mode; "
                    + "this simulator runs in real time");
        }
        return liveHandle();
    }

    private long liveHandle() {
        if (handle == 0) {
            throw new IllegalStateException("roq-sim simulator of course " + course.name() + " is closed");
        }
        return handle;
    }

    /** Stops the loop (real-time mode) and frees the native side. Idempotent. */
    @Override
    public synchronized void close() {
        if (handle == 0) {
            return;
        }
        if (options.mode() == SimMode.REAL_TIME) {
            RoqNative.stop(handle);
        }
        RoqNative.close(handle);
        handle = 0;
    }
}

package org.fdnet.roq.sim;

import java.lang.invoke.MethodHandles;
import java.lang.invoke.VarHandle;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.util.ArrayList;
import java.util.List;

/**
 * The pending {@link Stimulus}es, mirrored into the shared block's stimulus table under its own sequence (the same
 * seqlock protocol as the command slot): Java rewrites the whole table, the C tick takes it when the sequence has
 * moved and is even, and applies each entry in the ticks it spans.
 */
final class StimulusTable {
    private static final VarHandle LONGS = MethodHandles.byteBufferViewVarHandle(long[].class, ByteOrder.nativeOrder());

    private final ByteBuffer block;
    private final int fragileCells;
    private final List<Stimulus> pending = new ArrayList<>();

    StimulusTable(ByteBuffer block, int fragileCells) {
        this.block = block;
        this.fragileCells = fragileCells;
    }

    /** Adds {@code stimulus}, dropping those ended by {@code nowTick}, and publishes the table. */
    synchronized void add(Stimulus stimulus, long nowTick) {
        if (stimulus instanceof CellBreak b && b.cell() >= fragileCells) {
            throw new IllegalArgumentException("break cell " + b.cell() + ": the course has " + fragileCells
                    + " fragile cells (numbered from 0)");
        }
        pending.removeIf(x -> x.endTick() <= nowTick);
        if (pending.size() >= SharedBlockLayout.MAX_STIMULI) {
            throw new IllegalArgumentException("stimulus table full: " + pending.size() + " pushes and breaks still "
                    + "pending at tick " + nowTick + " (at most " + SharedBlockLayout.MAX_STIMULI + ")");
        }
        pending.add(stimulus);
        publish();
    }

    private void publish() {
        long seq = (long) LONGS.getOpaque(block, SharedBlockLayout.STIMULUS_SEQ);
        LONGS.setVolatile(block, SharedBlockLayout.STIMULUS_SEQ, seq + 1);
        VarHandle.releaseFence();
        block.putLong(SharedBlockLayout.X_COUNT, pending.size());
        for (int i = 0; i < pending.size(); i++) {
            Stimulus x = pending.get(i);
            int at = SharedBlockLayout.X_TABLE + SharedBlockLayout.X_ENTRY_SIZE * i;
            block.putLong(at + 8, x.firstTick());
            block.putLong(at + 16, x.endTick());
            if (x instanceof Push p) {
                block.putLong(at, SharedBlockLayout.X_KIND_PUSH);
                block.putDouble(at + 24, p.forceX());
                block.putDouble(at + 32, p.forceY());
                block.putDouble(at + 40, 0);
            } else if (x instanceof CellBreak b) {
                block.putLong(at, SharedBlockLayout.X_KIND_BREAK);
                block.putDouble(at + 24, b.cell());
                block.putDouble(at + 32, 0);
                block.putDouble(at + 40, 0);
            }
        }
        LONGS.setRelease(block, SharedBlockLayout.STIMULUS_SEQ, seq + 2);
    }
}

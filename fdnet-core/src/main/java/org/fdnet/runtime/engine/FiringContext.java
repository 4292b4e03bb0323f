package org.fdnet.runtime.engine;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Servants;
import org.fdnet.runtime.Value;

/**
 * The {@link RelationContext} of one Relation, reused for each of its firings (a Relation never fires
 * twice at once): the input snapshot and the pending outputs live in arrays, so a firing allocates
 * nothing of its own.
 */
final class FiringContext implements RelationContext {
    private final RelationNode node;
    private final Dataflow flow;
    private Wiring wiring = Wiring.EMPTY;
    private Value[] in = new Value[0];
    private long[] previousTimes = new long[0];
    private Value[] out = new Value[0];
    private boolean periodic;
    /** The newest source tick among the inputs this firing read: its outputs carry it ({@link Value#tick()}). */
    private long readTick;
    private long now;
    private String lastReport;

    FiringContext(RelationNode node, Dataflow flow) {
        this.node = node;
        this.flow = flow;
    }

    void begin(Wiring w, boolean periodicNow) {
        if (w != wiring) {
            wiring = w;
            in = new Value[w.inputs().length];
            previousTimes = new long[w.inputs().length];
            Arrays.fill(previousTimes, -1);
            out = new Value[w.outputs().length];
        }
        periodic = periodicNow;
        now = 0;
        readTick = 0;
        flow.snapshot(w.inputs(), in);
    }

    void commit(Wiring w) {
        for (int i = 0; i < in.length; i++) {
            previousTimes[i] = in[i] == null ? -1 : in[i].time();
        }
        for (int i = 0; i < out.length; i++) {
            if (out[i] != null && out[i].tick() < readTick) {
                out[i] = out[i].withTick(readTick);
            }
        }
        flow.commit(node, w.outputs(), out);
    }

    void discard() {
        Arrays.fill(out, null);
    }

    @Override
    public NodeRef self() {
        return node.ref;
    }

    @Override
    public int inputCount() {
        return in.length;
    }

    @Override
    public NodeRef inputRef(int index) {
        return wiring.inputRefs()[checkInput(index)];
    }

    @Override
    public Value input(int index) {
        return read(in[checkInput(index)]);
    }

    private Value read(Value v) {
        if (v != null && v.tick() > readTick) {
            readTick = v.tick();
        }
        return v;
    }

    private int checkInput(int index) {
        if (index < 0 || index >= in.length) {
            throw new IllegalArgumentException(node.ref + " has no input " + index + " (it reads " + in.length + ")");
        }
        return index;
    }

    @Override
    public Value input(String name) {
        int i = inputIndex(name);
        if (i < 0) {
            throw new IllegalArgumentException(node.ref + " does not read '" + name + "'");
        }
        return read(in[i]);
    }

    @Override
    public int inputIndex(String name) {
        return Wiring.indexOf(wiring.inputRefs(), name);
    }

    @Override
    public boolean inputChanged(int index) {
        checkInput(index);
        return in[index] != null && in[index].time() != previousTimes[index];
    }

    @Override
    public int outputCount() {
        return out.length;
    }

    @Override
    public NodeRef outputRef(int index) {
        return wiring.outputRefs()[index];
    }

    @Override
    public int outputIndex(String name) {
        return Wiring.indexOf(wiring.outputRefs(), name);
    }

    @Override
    public boolean outputPresent(int index) {
        return wiring.outputs()[index] != null;
    }

    @Override
    public Value outputValue(int index) {
        DataNode d = wiring.outputs()[index];
        return d == null ? null : d.value;
    }

    @Override
    public void output(int index, Value value) {
        if (index < 0 || index >= out.length) {
            throw new IllegalArgumentException(node.ref + " has no output " + index + " (it writes " + out.length + ")");
        }
        out[index] = value;
    }

    @Override
    public void output(String name, Value value) {
        int i = outputIndex(name);
        if (i < 0) {
            throw new IllegalArgumentException(node.ref + " does not write '" + name + "'");
        }
        out[i] = value;
    }

    @Override
    public long now() {
        if (now == 0) {
            now = flow.wallMicros();
        }
        return now;
    }

    @Override
    public double seconds() {
        return flow.secondsSinceStart();
    }

    @Override
    public boolean periodic() {
        return periodic;
    }

    @Override
    public void report(String status) {
        if (!status.equals(lastReport)) {
            lastReport = status;
            flow.events().relationValue(node.id, status);
        }
    }

    @Override
    public Servants servants() {
        // Not kept between firings: the distribution layer may install the whole network's view meanwhile.
        return flow.servantsFor(node);
    }

    @Override
    public List<NodeRef> missingInputs() {
        List<NodeRef> missing = new ArrayList<>();
        for (int i = 0; i < in.length; i++) {
            if (wiring.inputs()[i] == null) {
                missing.add(wiring.inputRefs()[i]);
            }
        }
        return missing;
    }
}

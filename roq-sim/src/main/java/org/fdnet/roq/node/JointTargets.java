package org.fdnet.roq.node;

import org.fdnet.event.ValueType;
import org.fdnet.roq.sim.RoqGeometry;
import org.fdnet.runtime.Data;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Value;

/**
 * RoQ's 12 joint servos as a Data: what a Relation writes here, the {@link org.fdnet.roq.bridge.SimBridge}
 * sends to the simulator's command slot (leg-major: fl, fr, hl, hr × yaw, lift, knee; rad). Starts at the
 * standing pose; a value of another length is refused.
 */
public class JointTargets extends Data {
    /** The targets always start at the standing pose, whatever a file gives. */
    public static final ParameterSpec<String> INITIAL = Data.INITIAL.defaultDescribed("the standing pose's angles")
            .describe("not read: the targets start at the standing pose");

    @Override
    public ValueType type() {
        return ValueType.DOUBLES;
    }

    @Override
    protected void init(NodeParameters p) {
    }

    @Override
    protected Value initialValue(NodeParameters p) {
        return Value.ofDoubles(RoqGeometry.standingTargets(new double[RoqGeometry.JOINTS]));
    }

    @Override
    protected Value accept(Value v) {
        if (v.length() != RoqGeometry.JOINTS) {
            throw new IllegalArgumentException("joint targets need " + RoqGeometry.JOINTS + " angles, got " + v.length());
        }
        return v;
    }
}

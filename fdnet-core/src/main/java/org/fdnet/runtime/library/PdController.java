package org.fdnet.runtime.library;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * A proportional-derivative controller: {@code u = kp e + kd de/dt}, {@code e = setpoint - measurement}.
 * The measurement is the input named by {@code measurement} (default: the first input); the set-point is
 * the input named by {@code setpointInput}, else the parameter {@code setpoint} (default 0). {@code kp}
 * is required, {@code kd} defaults to 0; {@code limit} (optional) bounds |u|. dt comes from the
 * measurement's timestamps; the first firing has no derivative.
 */
public class PdController extends Relation {
    private double kp;
    private double kd;
    private double setpoint;
    private double limit;
    private String measurementName;
    private String setpointName;
    private double lastError = Double.NaN;
    private long lastTime;

    @Override
    protected void init(NodeParameters p) {
        kp = p.requireDouble("kp");
        kd = p.doubleValue("kd", 0.0);
        setpoint = p.doubleValue("setpoint", 0.0);
        limit = p.doubleValue("limit", Double.POSITIVE_INFINITY);
        if (!(limit > 0)) {
            throw p.invalid("limit", "must be above 0, was " + limit);
        }
        measurementName = p.string("measurement", null);
        setpointName = p.string("setpointInput", null);
    }

    @Override
    protected void compute(RelationContext context) {
        int m = measurementName == null ? 0 : context.inputIndex(measurementName);
        if (m < 0 || m >= context.inputCount()) {
            throw new IllegalStateException(context.self() + " has no measurement input"
                    + (measurementName == null ? "" : " '" + measurementName + "'"));
        }
        Value measured = context.input(m);
        if (measured == null) {
            context.report("waiting for " + context.inputRef(m));
            return;
        }
        double target = setpoint;
        if (setpointName != null) {
            Value sp = context.input(setpointName);
            if (sp == null) {
                context.report("waiting for set-point " + setpointName);
                return;
            }
            target = sp.asDouble();
        }
        double error = target - measured.asDouble();
        double derivative = 0;
        if (!Double.isNaN(lastError) && measured.time() > lastTime) {
            derivative = (error - lastError) / ((measured.time() - lastTime) / 1e6);
        }
        lastError = error;
        lastTime = measured.time();
        double u = kp * error + kd * derivative;
        u = Math.max(-limit, Math.min(limit, u));
        context.outputAll(Value.of(u));
    }
}

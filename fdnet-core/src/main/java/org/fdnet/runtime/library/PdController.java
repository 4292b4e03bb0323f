package org.fdnet.runtime.library;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
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
    public static final ParameterSpec<Double> KP = ParameterSpec.number("kp").describe("the proportional gain").live();
    public static final ParameterSpec<Double> KD = ParameterSpec.number("kd").unit("s").defaultValue(0.0)
            .describe("the derivative gain").live();
    public static final ParameterSpec<Double> SETPOINT = ParameterSpec.number("setpoint").defaultValue(0.0)
            .describe("the set-point, when no input gives it").live();
    public static final ParameterSpec<Double> LIMIT = ParameterSpec.number("limit").above(0).defaultDescribed("none")
            .describe("the largest |u| written").live();
    public static final ParameterSpec<String> MEASUREMENT = ParameterSpec.text("measurement")
            .defaultDescribed("the first input").describe("the input that holds the measurement");
    public static final ParameterSpec<String> SETPOINT_INPUT = ParameterSpec.text("setpointInput").optional()
            .describe("the input that holds the set-point (instead of the parameter setpoint)");

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
        kp = KP.read(p);
        kd = KD.read(p);
        setpoint = SETPOINT.read(p);
        limit = LIMIT.readOr(p, Double.POSITIVE_INFINITY);
        measurementName = MEASUREMENT.read(p);
        setpointName = SETPOINT_INPUT.read(p);
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

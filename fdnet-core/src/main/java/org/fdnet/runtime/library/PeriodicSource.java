package org.fdnet.runtime.library;

import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * A signal generator: every {@code period} ms (required) writes {@code offset + amplitude * w(frequency * t + phase)}
 * to all its outputs, where {@code waveform} w is {@code sine} (default), {@code square}, {@code triangle},
 * {@code sawtooth} or {@code constant}; {@code amplitude} 1, {@code frequency} 1 Hz, {@code offset} 0,
 * {@code phase} 0 (in cycles). It stands in for a sensor or drives a test.
 */
public class PeriodicSource extends Relation {
    public static final ParameterSpec<Long> PERIOD = Relation.PERIOD.above(0).required()
            .describe("write every this many milliseconds");
    public static final ParameterSpec<String> WAVEFORM = ParameterSpec.choice("waveform",
            "sine", "square", "triangle", "sawtooth", "constant").defaultValue("sine").describe("the signal's shape").live();
    public static final ParameterSpec<Double> AMPLITUDE = ParameterSpec.number("amplitude").defaultValue(1.0)
            .describe("the signal's amplitude").live();
    public static final ParameterSpec<Double> FREQUENCY = ParameterSpec.number("frequency").unit("Hz").defaultValue(1.0)
            .describe("the signal's frequency").live();
    public static final ParameterSpec<Double> OFFSET = ParameterSpec.number("offset").defaultValue(0.0)
            .describe("added to the signal").live();
    public static final ParameterSpec<Double> PHASE = ParameterSpec.number("phase").unit("cycles").defaultValue(0.0)
            .describe("the signal's phase at time 0").live();

    private String waveform;
    private double amplitude;
    private double frequency;
    private double offset;
    private double phase;

    @Override
    protected void init(NodeParameters p) {
        waveform = WAVEFORM.read(p);
        amplitude = AMPLITUDE.read(p);
        frequency = FREQUENCY.read(p);
        offset = OFFSET.read(p);
        phase = PHASE.read(p);
    }

    @Override
    protected void compute(RelationContext context) {
        context.outputAll(Value.of(valueAt(context.seconds())));
    }

    double valueAt(double seconds) {
        double cycles = frequency * seconds + phase;
        double frac = cycles - Math.floor(cycles);
        double w = switch (waveform) {
            case "sine" -> Math.sin(2 * Math.PI * cycles);
            case "square" -> frac < 0.5 ? 1.0 : -1.0;
            case "triangle" -> frac < 0.5 ? 4 * frac - 1 : 3 - 4 * frac;
            case "sawtooth" -> 2 * frac - 1;
            default -> 1.0;
        };
        return offset + amplitude * w;
    }
}

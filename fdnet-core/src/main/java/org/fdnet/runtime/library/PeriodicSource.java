package org.fdnet.runtime.library;

import java.util.Locale;
import org.fdnet.runtime.NodeParameters;
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
    private String waveform;
    private double amplitude;
    private double frequency;
    private double offset;
    private double phase;

    @Override
    protected void init(NodeParameters p) {
        p.requireLong("period");
        waveform = p.string("waveform", "sine").strip().toLowerCase(Locale.ROOT);
        amplitude = p.doubleValue("amplitude", 1.0);
        frequency = p.doubleValue("frequency", 1.0);
        offset = p.doubleValue("offset", 0.0);
        phase = p.doubleValue("phase", 0.0);
        if (!java.util.Set.of("sine", "square", "triangle", "sawtooth", "constant").contains(waveform)) {
            throw p.invalid("waveform", "must be sine, square, triangle, sawtooth or constant, was '" + waveform + "'");
        }
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

package org.fdnet.runtime.library;

import java.util.ArrayList;
import java.util.List;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Value;

/**
 * The integration of the thesis's Figure 5: blends candidate postures into the goal of the next posture,
 * weighted by a judgment. Inputs: the candidates (every input but the two named below), the judgment Data
 * named by {@code judgment} (a number in [0, 1]: 0 = do not move, 1 = move fully; a boolean counts as 0/1),
 * and optionally the present posture named by {@code present}.
 *
 * <p>Each candidate's weight goes linearly from {@code weights} (at judgment 0) to {@code movingWeights}
 * (at judgment 1), one per candidate in input order (default: equal). The goal is the weighted mean of
 * the candidates; with a present posture and {@code gain} g (0 &lt; g ≤ 1, default 1) the output moves g
 * of the way from the present posture to the goal, so writing it back into the present posture (the
 * posture feedback loop) converges smoothly. "Move, but just a little" is a judgment between 0 and 1.
 */
public class Integration extends Relation {
    public static final ParameterSpec<String> JUDGMENT = ParameterSpec.text("judgment")
            .describe("the input that holds the judgment (0: do not move, 1: move fully)");
    public static final ParameterSpec<String> PRESENT = ParameterSpec.text("present").optional()
            .describe("the input that holds the present posture");
    public static final ParameterSpec<double[]> WEIGHTS = ParameterSpec.numbers("weights").atLeast(0)
            .defaultDescribed("equal").describe("each candidate's weight at judgment 0, in input order").live();
    public static final ParameterSpec<double[]> MOVING_WEIGHTS = ParameterSpec.numbers("movingWeights").atLeast(0)
            .defaultDescribed("weights").describe("each candidate's weight at judgment 1, in input order").live();
    public static final ParameterSpec<Double> GAIN = ParameterSpec.number("gain").above(0).atMost(1).defaultValue(1.0)
            .describe("the share of the way from the present posture to the goal taken each firing").live();

    private String judgmentName;
    private String presentName;
    private double[] still;
    private double[] moving;
    private double gain;

    @Override
    protected void init(NodeParameters p) {
        judgmentName = JUDGMENT.read(p);
        presentName = PRESENT.read(p);
        still = WEIGHTS.read(p);
        moving = MOVING_WEIGHTS.readOr(p, still);
        gain = GAIN.read(p);
        if (still != null && moving != null && still.length != moving.length) {
            throw p.conflict(MOVING_WEIGHTS, WEIGHTS, "movingWeights must have as many weights as weights");
        }
    }

    @Override
    protected void compute(RelationContext context) {
        int judgmentIndex = context.inputIndex(judgmentName);
        if (judgmentIndex < 0) {
            throw new IllegalStateException(context.self() + " has no input '" + judgmentName + "' (parameter judgment)");
        }
        int presentIndex = presentName == null ? -1 : context.inputIndex(presentName);
        Value judgmentValue = context.input(judgmentIndex);
        double j = judgmentValue == null ? 0.0 : Math.max(0, Math.min(1, judgmentValue.asDouble()));
        List<Value> candidates = new ArrayList<>();
        List<Integer> slots = new ArrayList<>();
        int slot = 0;
        for (int i = 0; i < context.inputCount(); i++) {
            if (i == judgmentIndex || i == presentIndex) {
                continue;
            }
            if (context.input(i) != null) {
                candidates.add(context.input(i));
                slots.add(slot);
            }
            slot++;
        }
        if (still != null && still.length != slot) {
            throw new IllegalStateException(context.self() + " has " + slot + " candidates but " + still.length + " weights");
        }
        if (candidates.isEmpty()) {
            context.report("waiting for candidates");
            return;
        }
        int n = candidates.get(0).length();
        double[] goal = new double[n];
        double total = 0;
        for (int c = 0; c < candidates.size(); c++) {
            Value v = candidates.get(c);
            if (v.length() != n) {
                throw new IllegalStateException("candidate " + context.inputRef(c) + " has " + v.length()
                        + " values, the first has " + n);
            }
            int k = slots.get(c);
            double w = still == null ? 1.0 : still[k] + (moving[k] - still[k]) * j;
            for (int i = 0; i < n; i++) {
                goal[i] += w * v.element(i);
            }
            total += w;
        }
        if (total <= 0) {
            context.report("all weights are zero at judgment " + j);
            return;
        }
        for (int i = 0; i < n; i++) {
            goal[i] /= total;
        }
        Value present = presentIndex < 0 ? null : context.input(presentIndex);
        if (present != null && present.length() == n && gain < 1) {
            for (int i = 0; i < n; i++) {
                goal[i] = present.element(i) + gain * (goal[i] - present.element(i));
            }
        }
        context.report(String.format(java.util.Locale.ROOT, "judgment %.2f", j));
        context.outputAll(n == 1 && candidates.get(0).isScalar() ? Value.of(goal[0]) : Value.ofDoubles(goal));
    }
}

package org.fdnet.runtime.library;

import java.util.List;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.runtime.NodeDescription;
import org.fdnet.runtime.NodeParameters;
import org.fdnet.runtime.ParameterSpec;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationContext;
import org.fdnet.runtime.Servants;

/**
 * Self-organization at work: watches the network (Visitor) for running sensor Datas — of class
 * {@code sensorClass}, default {@link DoubleSensor} — and gives each one that has none a low-pass filter:
 * it creates (Paste) a Data {@code <sensor> filtered} and a {@link LowPass} Relation {@code <sensor> filter}
 * with {@code alpha} (default 0.2) reading the sensor and writing the filtered Data, in module
 * {@code module} (default: the sensor's own), on the sensor's host. Looks every {@code period} ms (give it one) and when an
 * input changes. Reports how many filters it made.
 */
public class AutoFilter extends Relation {
    public static final ParameterSpec<String> SENSOR_CLASS = ParameterSpec.text("sensorClass")
            .defaultValue(DoubleSensor.class.getName()).describe("the class of the sensor Datas that get a filter").live();
    public static final ParameterSpec<Double> ALPHA = ParameterSpec.number("alpha").above(0).atMost(1).defaultValue(0.2)
            .describe("the alpha of each filter it makes (LowPass)").live();
    public static final ParameterSpec<String> MODULE = ParameterSpec.text("module").defaultDescribed("the sensor's module")
            .describe("the module the filters are made in").live();

    private String sensorClass;
    private String alpha;
    private String module;
    private int made;

    @Override
    protected void init(NodeParameters p) {
        sensorClass = SENSOR_CLASS.read(p);
        alpha = Double.toString(ALPHA.read(p));
        module = MODULE.read(p);
    }

    @Override
    protected void compute(RelationContext context) {
        Servants servants = context.servants();
        for (NodeDescription sensor : servants.visitor().byClass(sensorClass)) {
            NodeRef ref = sensor.ref();
            String target = module == null ? ref.module() : module;
            NodeRef filter = new NodeRef(target, ref.node() + " filter");
            if (servants.reflect().describe(filter) != null) {
                continue;
            }
            // the filter lives with its sensor: on a network over several hosts, on the sensor's host
            NodeInfo filtered = NodeInfo.data(ref.node() + " filtered", DoubleData.class.getName())
                    .withHost(sensor.host());
            NodeInfo relation = NodeInfo.relation(filter.node(), LowPass.class.getName(), Parameter.named("alpha", alpha))
                    .withHost(sensor.host());
            var outcome = servants.paste().pasteRelation(target, relation, List.of(filtered), List.of(ref),
                    List.of(new NodeRef(target, filtered.name())));
            if (outcome.executed()) {
                made++;
            } else {
                context.report("could not filter " + ref + ": " + outcome.reason());
            }
        }
        context.report("filters made: " + made);
    }
}

package org.fdnet.testkit;

import java.nio.file.Path;
import java.time.Duration;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Objects;
import java.util.function.Predicate;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.event.NetworkEvent;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.RelationState;
import org.fdnet.runtime.RelationStatus;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.engine.DrivenClock;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.runtime.engine.RuntimeStartException;
import org.fdnet.runtime.loading.ClassLoadingPolicy;

/**
 * A network running in a test on a <b>driven clock</b>: nothing fires until the test advances simulated time, and
 * every firing runs on the test's thread, so the same test gives the same values, time stamps included, and never
 * waits for a wall clock. Every event is kept in memory for {@link #history} and {@link #events}; there is no
 * CORBA and no database.
 *
 * <p>Nodes are named {@code Module/Node}, or by a bare name for module {@code main}. Values are set with
 * {@link #set} as a Relation would write them and read with {@link #value} or asserted with {@link #assertValue};
 * {@link #await} advances in {@link #STEP} steps until a condition holds or a simulated deadline passes.
 *
 * <pre>{@code
 * try (TestNetwork net = TestNetwork.start(Path.of("networks/lab.fdn"))) {
 *     net.set("Lab/input", 0.5);
 *     net.advance(Duration.ofMillis(20));
 *     net.assertValue("Lab/output").isCloseTo(1.0, 1e-9);
 * }
 * }</pre>
 *
 * <p>Node classes: built-in ones (FDNet's library, RoQ's nodes) and those under a node's {@code path}; a path may
 * point anywhere under the network file's folder or the folder the tests run in (the project's), so a network in
 * {@code networks/} can name {@code ../target/classes}.
 */
public final class TestNetwork implements AutoCloseable {
    /** The step {@link #await} advances by: 1 ms of simulated time. */
    public static final Duration STEP = Duration.ofMillis(1);

    private final RuntimeNetwork network;
    private final MemoryEventSink events;
    private final long startMicros;
    private final String name;

    private TestNetwork(RuntimeNetwork network, MemoryEventSink events, long startMicros, String name) {
        this.network = network;
        this.events = events;
        this.startMicros = startMicros;
        this.name = name;
    }

    /**
     * Starts the network in {@code fdn} on a driven clock at simulated time 0.
     *
     * @param fdn a {@code .fdn} file, relative to the working directory or absolute
     * @return the running network; close it (or let {@link FdnetExtension} do it)
     * @throws IllegalArgumentException naming the file and every problem when it does not load or start
     */
    public static TestNetwork start(Path fdn) {
        NetworkInfo definition;
        try {
            definition = NetworkRepository.load(fdn);
        } catch (NetworkFileException e) {
            throw new IllegalArgumentException(fdn + " does not load: " + e.getMessage(), e);
        }
        return start(definition, ClassLoadingPolicy.forNetworkFile(fdn,
                List.of(Path.of("").toAbsolutePath())), fdn.toString());
    }

    /**
     * Starts a network built in code (built-in node classes only) on a driven clock at simulated time 0.
     *
     * @param definition the network, e.g. made with {@code NetworkInfo}'s edits
     * @return the running network; close it
     * @throws IllegalArgumentException naming every problem when it does not start
     */
    public static TestNetwork start(NetworkInfo definition) {
        return start(definition, ClassLoadingPolicy.builtInOnly(), definition.name());
    }

    /**
     * Starts {@code definition} on a driven clock with {@code policy} for its node classes; the way the robot kit
     * starts a network beside a simulator.
     *
     * @param definition the network
     * @param policy     where its node classes may come from
     * @param name       what failure messages call it (a file name)
     * @return the running network; close it
     * @throws IllegalArgumentException naming every problem when it does not start
     */
    public static TestNetwork start(NetworkInfo definition, ClassLoadingPolicy policy, String name) {
        return start(definition, policy, name, 0);
    }

    /**
     * As {@link #start(NetworkInfo, ClassLoadingPolicy, String)}, with the driven clock standing at
     * {@code startMicros} (the robot kit starts at the wall-clock time of the test, so a recorded run shows when it
     * ran; {@link #time()} still counts from 0).
     *
     * @param definition  the network
     * @param policy      where its node classes may come from
     * @param name        what failure messages call it
     * @param startMicros the driven clock's start, µs since the epoch
     * @return the running network; close it
     * @throws IllegalArgumentException naming every problem when it does not start
     */
    public static TestNetwork start(NetworkInfo definition, ClassLoadingPolicy policy, String name, long startMicros) {
        MemoryEventSink events = new MemoryEventSink();
        long start = startMicros;
        try {
            RuntimeNetwork network = RuntimeNetwork.start(definition, RuntimeOptions.defaults()
                    .drivenClock(new DrivenClock(start)).classLoading(policy).sink(events));
            return new TestNetwork(network, events, start, name);
        } catch (RuntimeStartException e) {
            throw new IllegalArgumentException(name + " does not start: " + String.join("; ", e.problems()), e);
        }
    }

    /**
     * Moves simulated time forward by {@code duration}, firing every period that falls due on the way and
     * everything each firing causes.
     *
     * @param duration how far, ≥ 0
     */
    public void advance(Duration duration) {
        if (duration.isNegative()) {
            throw new IllegalArgumentException("advance by a negative duration: " + duration);
        }
        network.advanceTo(network.timeMicros() + duration.toNanos() / 1000);
    }

    /** @return the simulated time since the network started */
    public Duration time() {
        return Duration.ofNanos((network.timeMicros() - startMicros) * 1000);
    }

    /**
     * Writes {@code value} into a Data as a Relation would; its readers fire before this returns.
     *
     * @param node  {@code Module/Node}, or a bare name in module main
     * @param value a {@link Value}, a {@code Double}, {@code Long}, {@code Integer}, {@code Boolean} or a {@code String}
     *              (converted to the Data's type as a written value is)
     */
    public void set(String node, Object value) {
        network.controller().setValue(ref(node), toValue(value));
        network.advanceTo(network.timeMicros());
    }

    /**
     * Sends a text to a Data the way {@code fdnet run}'s {@code send} does.
     *
     * @param node {@code Module/Node}
     * @param text the value in the Data's text form
     * @throws AssertionError when the network refuses it
     */
    public void send(String node, String text) {
        expectExecuted(network.controller().send(ref(node), text));
        network.advanceTo(network.timeMicros());
    }

    /**
     * @param node {@code Module/Node}
     * @return the Data's current value, or {@code null} when it has none or its module is not loaded
     * @throws IllegalArgumentException when the network defines no Data of that name
     */
    public Value value(String node) {
        return network.controller().value(dataRef(node));
    }

    /**
     * @param node {@code Module/Node}
     * @return an assertion on the Data's current value whose failures name the node and the simulated time
     */
    public ValueAssertion assertValue(String node) {
        return new ValueAssertion(node, value(node), time());
    }

    /**
     * Every value the Data took since the network started, oldest first.
     *
     * @param node {@code Module/Node}
     * @return the values, with their time stamps
     */
    public List<Value> history(String node) {
        int id = network.controller().nodeId(dataRef(node));
        List<Value> values = new ArrayList<>();
        for (DataValueEvent e : events.events(DataValueEvent.class)) {
            if (e.sourceId() == id) {
                values.add(Value.of(e.value()).at(e.time()));
            }
        }
        return values;
    }

    /**
     * Advances in {@link #STEP}s until {@code condition} holds, at most {@code timeout} of simulated time.
     *
     * @param description what is awaited, for the failure message
     * @param condition   tested before the first step and after each
     * @param timeout     simulated time to wait at most
     * @throws AssertionError naming the description and the simulated time when the timeout passes
     */
    public void await(String description, Predicate<TestNetwork> condition, Duration timeout) {
        Duration deadline = time().plus(timeout);
        while (!condition.test(this)) {
            if (time().compareTo(deadline) >= 0) {
                throw new AssertionError(String.format(Locale.ROOT, "%s: %s did not happen within %s of simulated"
                        + " time (now t = %s)", name, description, seconds(timeout), seconds(time())));
            }
            advance(STEP);
        }
    }

    /**
     * Advances until the Data's value satisfies {@code condition}, at most {@code timeout} of simulated time.
     *
     * @param node      {@code Module/Node}
     * @param condition tested on each value the Data has after a step (never on {@code null})
     * @param timeout   simulated time to wait at most
     * @return the value that satisfied it
     * @throws AssertionError naming the node, its last value and the simulated time when the timeout passes
     */
    public Value awaitValue(String node, Predicate<Value> condition, Duration timeout) {
        Duration deadline = time().plus(timeout);
        while (true) {
            Value v = value(node);
            if (v != null && condition.test(v)) {
                return v;
            }
            if (time().compareTo(deadline) >= 0) {
                throw new AssertionError(String.format(Locale.ROOT, "%s: %s never met the condition within %s of"
                        + " simulated time (now t = %s, last value %s)", name, node, seconds(timeout), seconds(time()),
                        ValueAssertion.describe(v)));
            }
            advance(STEP);
        }
    }

    /**
     * Changes a node's parameter while the network runs, as the editor's live mode does.
     *
     * @throws AssertionError when the network refuses the change, with its reason
     */
    public void setParameter(String node, String parameter, String value) {
        expectExecuted(network.controller().setParameter(ref(node), parameter, value));
    }

    /** Loads a module. @throws AssertionError when the network refuses, with its reason */
    public void load(String module) {
        expectExecuted(network.controller().load(module));
    }

    /** Unloads a module. @throws AssertionError when the network refuses, with its reason */
    public void unload(String module) {
        expectExecuted(network.controller().unload(module));
    }

    /** @return every event the network emitted since it started, in order */
    public List<NetworkEvent> events() {
        return events.events();
    }

    /** @return the Relations an exception stopped, each with its cause */
    public List<RelationState> relationFailures() {
        return network.controller().relationStates().stream()
                .filter(s -> s.status() == RelationStatus.FAILED).toList();
    }

    /** @return the network's controller, for anything this class does not wrap */
    public Controller controller() {
        return network.controller();
    }

    /** @return the driven clock's start, µs since the epoch */
    public long startMicros() {
        return startMicros;
    }

    /** @return the engine underneath, for the robot kit's simulator bridge */
    public RuntimeNetwork engine() {
        return network;
    }

    /** @return what failure messages call this network */
    public String name() {
        return name;
    }

    @Override
    public void close() {
        network.close();
    }

    private NodeRef dataRef(String node) {
        NodeRef ref = ref(node);
        boolean isData = network.readDefinition(d -> d.node(ref) != null
                && d.node(ref).kind() == NodeKind.DATA);
        if (!isData) {
            throw new IllegalArgumentException(name + " has no Data " + ref);
        }
        return ref;
    }

    static NodeRef ref(String node) {
        Objects.requireNonNull(node, "node");
        return NodeRef.parse(node, "main");
    }

    static String seconds(Duration d) {
        return String.format(Locale.ROOT, "%.3f s", d.toNanos() / 1e9);
    }

    private void expectExecuted(ChangeOutcome outcome) {
        if (!outcome.executed()) {
            throw new AssertionError(name + ": " + outcome.description() + " was refused at t = " + seconds(time())
                    + ": " + outcome.reason());
        }
    }

    private static Value toValue(Object value) {
        if (value instanceof Value v) {
            return v;
        } else if (value instanceof Double d) {
            return Value.of(d);
        } else if (value instanceof Float f) {
            return Value.of(f.doubleValue());
        } else if (value instanceof Long l) {
            return Value.of(l);
        } else if (value instanceof Integer i) {
            return Value.of(i.longValue());
        } else if (value instanceof Boolean b) {
            return Value.of(b);
        } else if (value instanceof String s) {
            return Value.of(s);
        } else if (value instanceof double[] doubles) {
            return Value.ofDoubles(doubles);
        }
        throw new IllegalArgumentException("a value is a Value, Double, Long, Integer, Boolean, String or double[],"
                + " not " + (value == null ? "null" : value.getClass().getName()));
    }
}

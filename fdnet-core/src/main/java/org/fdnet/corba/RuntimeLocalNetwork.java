package org.fdnet.corba;

import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.NoSuchElementException;
import java.util.Optional;
import java.util.Set;
import java.util.UUID;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.RunIdentity;
import org.fdnet.event.ValueType;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.NetworkEdit;
import org.fdnet.runtime.Placement;
import org.fdnet.runtime.RemoteLink;
import org.fdnet.runtime.ServantRegistry;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.WholeNetwork;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.runtime.engine.RuntimeStartException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A host's share of a distributed network, run by the single-host engine ({@link RuntimeNetwork}).
 *
 * <p>The host keeps a definition of its own: nodes created here carry this host's name; stand-ins carry
 * their home host's, so the engine's {@link Placement} makes them local shadows (it does so once a local
 * Relation is connected to them). Every request is a change request of the engine's {@link Controller};
 * a refused one throws with the engine's reason. A value injected from a link is set with its origin held
 * in a thread-local {@link Injection}: the engine tells its observers on the writing thread, so each
 * observer of that Data learns where that value came from and a link never echoes it back to its sender.
 * The origin belongs to the injected value only: what a Relation fired by it writes afterwards on the same
 * thread is this host's own value (a controller's command goes back to the host its sensor is on).
 */
public final class RuntimeLocalNetwork implements LocalNetwork, AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(RuntimeLocalNetwork.class);
    private static final ThreadLocal<Injection> INJECTING = ThreadLocal.withInitial(Injection::new);

    private final String hostName;
    private final RuntimeNetwork runtime;
    private final Controller controller;
    private final Set<NodeRef> standIns = ConcurrentHashMap.newKeySet();
    private String ownLogger; // guarded by this
    private volatile HostRecording recording; // changed under this
    private volatile Consumer<String> runEnded = report -> { };
    private volatile HostTrace trace; // changed under this
    private final int ownWorkers; // fdnet host --workers, else one per core: a run that names none gets these

    /** The most worker threads a run may ask a host for; the most events a host keeps for a run's trace. */
    public static final int MAX_WORKERS = 256;
    static final int MAX_TRACE_CAPACITY = 1_000_000;

    private RuntimeLocalNetwork(String hostName, RuntimeNetwork runtime) {
        this.hostName = hostName;
        this.runtime = runtime;
        this.controller = runtime.controller();
        this.ownWorkers = runtime.workerThreads();
    }

    /** Starts an empty engine whose local nodes are those placed on {@code hostName}. */
    public static RuntimeLocalNetwork start(String hostName, RuntimeOptions options) {
        options.placement(Placement.forHostNames(Set.of(hostName)));
        try {
            return new RuntimeLocalNetwork(hostName, RuntimeNetwork.start(new NetworkInfo(hostName), options));
        } catch (RuntimeStartException e) {
            throw new IllegalStateException("the engine of host " + hostName + " did not start: " + e.problems(), e);
        }
    }

    /**
     * Records every network run this host serves with the logger at {@code hostPort} ({@code fdnet host --logger}),
     * whatever address the run's coordinator hands over.
     *
     * @throws IllegalArgumentException when {@code hostPort} is not {@code HOST:PORT}
     */
    public synchronized void recordWith(String hostPort) {
        LoggerClientSettings.parseAddress(hostPort, coreName());
        ownLogger = hostPort;
    }

    /**
     * From now on records this host's events — less its stand-ins' — as its part of {@code run}, with this host's
     * own logger or else the one at {@code hostPort}; a run recorded before ends first (its events committed).
     * {@code false} when nothing is recorded (no logger at all) or {@code run} already is.
     *
     * @throws IllegalArgumentException when the address is not {@code HOST:PORT}
     */
    @Override
    public synchronized boolean recordRun(String hostPort, RunIdentity run, long clockOffsetMicros) {
        String address = ownLogger != null ? ownLogger : hostPort;
        if (address == null || address.isEmpty() || (recording != null && recording.run().id().equals(run.id()))) {
            return false;
        }
        LoggerClientSettings settings = LoggerClientSettings.parseAddress(address, coreName());
        if (recording != null) {
            endRun(recording.run().id());
        }
        recording = new HostRecording(new LoggerClient(settings, run, hostName, clockOffsetMicros),
                standIns::contains);
        runtime.addSink(recording);
        LOG.info("host {} records its part of {} run {} with the logger at {}", hostName, run.network(), run.id(),
                address);
        return true;
    }

    /** Ends the recording of {@code run} (bounded wait for the logger's commits); what was committed, if recorded. */
    @Override
    public synchronized Optional<String> endRun(UUID run) {
        if (recording == null || !recording.run().id().equals(run)) {
            return Optional.empty();
        }
        HostRecording ending = recording;
        recording = null;
        runtime.removeSink(ending);
        String report = ending.end();
        LOG.info("host {}: {} run {}: {}", hostName, ending.run().network(), run, report);
        runEnded.accept(report);
        return Optional.of(report);
    }

    @Override
    public synchronized int sizeEngine(int workers) {
        if (workers < 0 || workers > MAX_WORKERS) {
            throw new IllegalArgumentException("--workers " + workers + ": host " + hostName + " runs 1 to "
                    + MAX_WORKERS + " worker threads");
        }
        int threads = workers == 0 ? ownWorkers : workers;
        if (threads != runtime.workerThreads()) {
            runtime.resizeWorkers(threads);
            LOG.info("host {} runs {} worker threads", hostName, threads);
        }
        return runtime.workerThreads();
    }

    @Override
    public synchronized void traceRun(UUID run, int capacity) {
        if (capacity < 1 || capacity > MAX_TRACE_CAPACITY) {
            throw new IllegalArgumentException("a trace keeps 1 to " + MAX_TRACE_CAPACITY + " events, not "
                    + capacity);
        }
        if (trace != null) {
            if (trace.run().equals(run)) {
                return; // told again (a structural change brought this host in again): keep what is kept
            }
            runtime.removeSink(trace);
        }
        trace = new HostTrace(run, capacity, standIns::contains);
        runtime.addSink(trace);
        LOG.info("host {} keeps up to {} of its events of run {} for the run's trace", hostName, capacity, run);
    }

    @Override
    public HostTrace.Batch takeTrace(UUID run, int max) {
        HostTrace t = trace;
        return t == null || !t.run().equals(run) ? HostTrace.Batch.EMPTY : t.take(max);
    }

    @Override
    public synchronized void endTrace(UUID run) {
        if (trace != null && trace.run().equals(run)) {
            runtime.removeSink(trace);
            trace = null;
        }
    }

    /** Told what the logger committed each time a run's recording ends here (fdnet host prints it). */
    public void onRunEnded(Consumer<String> listener) {
        runEnded = listener;
    }

    /** The client recording this host's part of the current run, if any (its status says what is committed). */
    public synchronized Optional<LoggerClient> logger() {
        return Optional.ofNullable(recording).map(HostRecording::client);
    }

    /** Records {@code event} (a host or link event of the deployment) with this host's part of the current run. */
    public void record(NetworkEvent event) {
        HostRecording r = recording;
        if (r != null) {
            r.accept(event);
        }
    }

    @Override
    public void expectStandIn(NodeRef ref) {
        standIns.add(ref);
    }

    private String coreName() {
        return "fdnet host " + hostName;
    }

    @Override
    public Optional<Controller> controller() {
        return Optional.of(controller);
    }

    @Override
    public Optional<ServantRegistry> servants() {
        return Optional.of(runtime.servantRegistry());
    }

    public RuntimeNetwork runtime() {
        return runtime;
    }

    @Override
    public void create(NodeRef ref, NodeInfo node) {
        ensureModule(ref.module());
        apply("create " + ref, n -> n.addNode(ref.module(), node.withHost(hostName)));
    }

    @Override
    public void load(String module, List<NodeInfo> nodes, List<ConnectionInfo> connections) {
        boolean known = runtime.readDefinition(d -> d.module(module)) != null;
        apply("load " + module + " on " + hostName, n -> {
            if (!known) {
                n.addModule(module, true);
            }
            for (NodeInfo node : nodes) {
                n.addNode(module, node.withHost(hostName));
            }
            for (ConnectionInfo c : connections) {
                n.addConnection(module, c);
            }
        });
        if (!controller.loadedModules().contains(module)) {
            ChangeOutcome loaded = controller.load(module);
            if (!loaded.executed()) {
                throw new IllegalStateException(loaded.reason());
            }
        }
    }

    @Override
    public String check(String description, NetworkEdit edit) {
        try {
            String problem = runtime.check(edit, true); // reshape loads the modules the edit adds
            return problem == null ? null : description + ": " + problem;
        } catch (RuntimeException e) {
            return description + ": " + (e.getMessage() == null ? e.toString() : e.getMessage());
        }
    }

    @Override
    public void reshape(String description, NetworkEdit edit) {
        Set<String> before = moduleNames();
        apply(description + " on " + hostName, edit);
        for (String module : moduleNames()) {
            if (!before.contains(module) && !controller.loadedModules().contains(module)) {
                ChangeOutcome loaded = controller.load(module);
                if (!loaded.executed()) {
                    throw new IllegalStateException(loaded.reason());
                }
            }
        }
    }

    private Set<String> moduleNames() {
        return runtime.readDefinition(d -> {
            Set<String> names = new LinkedHashSet<>();
            d.modules().forEach(m -> names.add(m.name()));
            return names;
        });
    }

    @Override
    public void seeWholeNetwork(WholeNetwork whole) {
        runtime.seeWholeNetwork(whole);
    }

    @Override
    public void createStandIn(NodeRef ref, NodeInfo node) {
        ensureModule(ref.module());
        if (runtime.readDefinition(d -> d.node(ref)) != null) {
            return; // already declared: several connections share one stand-in
        }
        standIns.add(ref);
        apply("declare remote " + ref, n -> n.addNode(ref.module(), node));
    }

    @Override
    public void destroy(NodeRef ref) {
        if (runtime.readDefinition(d -> d.node(ref)) == null) {
            throw new NoSuchElementException(ref.toString());
        }
        apply("destroy " + ref, n -> n.deleteNode(ref));
    }

    @Override
    public List<NodeRef> nodes() {
        Set<NodeRef> refs = new LinkedHashSet<>();
        Set<String> loaded = controller.loadedModules();
        runtime.readDefinition(d -> {
            for (ModuleInfo m : d.modules()) {
                if (loaded.contains(m.name())) {
                    for (NodeInfo n : m.nodes()) {
                        if (n.host().equals(hostName)) {
                            refs.add(new NodeRef(m.name(), n.name()));
                        }
                    }
                }
            }
            return null;
        });
        for (RemoteLink link : controller.remoteLinks()) {
            if (link.standIn() && !link.broken()) {
                refs.add(link.connection().data());
            }
        }
        return new ArrayList<>(refs);
    }

    @Override
    public boolean knows(NodeRef ref) {
        return runtime.readDefinition(d -> d.node(ref)) != null;
    }

    @Override
    public void connect(ConnectionInfo connection) {
        apply("connect " + connection, n -> n.addConnection(connection.relation().module(), connection));
    }

    @Override
    public void disconnect(ConnectionInfo connection) {
        apply("disconnect " + connection, n -> n.deleteConnection(connection.relation().module(), connection));
    }

    @Override
    public Object read(NodeRef data) {
        Value v = controller.value(data);
        return v == null ? null : toJava(v);
    }

    @Override
    public void write(NodeRef data, Object value) {
        controller.setValue(data, toRuntime(value));
    }

    @Override
    public void inject(NodeRef data, Object value, String originHost, ValueOrigin origin) {
        Injection current = INJECTING.get();
        // an injection while another is under way on this thread gets a record of its own; the outer one comes back
        Injection injection = current.active() ? new Injection() : current;
        if (injection != current) {
            INJECTING.set(injection);
        }
        injection.begin(data, originHost, origin);
        try {
            controller.setValue(data, toRuntime(value));
        } finally {
            injection.end();
            if (injection != current) {
                INJECTING.set(current);
            }
        }
    }

    @Override
    public AutoCloseable observe(NodeRef data, ValueObserver observer) {
        return controller.observe(data, (ref, id, value) -> {
            Injection injection = INJECTING.get();
            if (injection.isOf(ref, value)) {
                observer.onValue(toJava(value), injection.host, injection.origin);
            } else {
                observer.onValue(toJava(value), null, null);
            }
        });
    }

    /**
     * A value a link is setting on this thread. The engine stores it (telling the Data's observers) before
     * its readers fire, so the first value of {@link #data} stored on this thread is the injected one; any
     * later value — of that Data or another, written by a Relation the injected value fired — is local.
     */
    private static final class Injection {
        private NodeRef data;
        private String host;
        private ValueOrigin origin;
        private Value stored;

        /** One per thread, reused for every value a link injects on it: a link applies millions a second. */
        void begin(NodeRef injected, String fromHost, ValueOrigin from) {
            this.data = injected;
            this.host = fromHost;
            this.origin = from;
            this.stored = null;
        }

        void end() {
            data = null;
            host = null;
            origin = null;
            stored = null;
        }

        boolean active() {
            return data != null;
        }

        /** Whether {@code value}, stored in {@code ref}, is the injected value (each observer asks). */
        boolean isOf(NodeRef ref, Value value) {
            if (stored != null) {
                return stored == value; // each store is a value of its own: the same object is the same Data's
            }
            if (data == null || !data.equals(ref)) {
                return false;
            }
            stored = value;
            return true;
        }
    }

    private void ensureModule(String module) {
        if (runtime.readDefinition(d -> d.module(module)) != null) {
            return;
        }
        apply("add module " + module, n -> n.addModule(module, true));
        ChangeOutcome loaded = controller.load(module);
        if (!loaded.executed()) {
            throw new IllegalStateException(loaded.reason());
        }
    }

    private void apply(String what, NetworkEdit edit) {
        ChangeOutcome outcome = controller.apply(what, edit);
        if (!outcome.executed()) {
            throw new IllegalStateException(outcome.reason());
        }
    }

    static Object toJava(Value v) {
        return switch (v.type()) {
            case LONG -> v.asLong();
            case DOUBLE -> v.asDouble();
            case BOOLEAN -> v.asBoolean();
            case STRING -> v.text();
            case BYTES -> v.asBytes();
            case DOUBLES -> v.asDoubles();
        };
    }

    static Value toRuntime(Object o) {
        if (o instanceof Long l) {
            return Value.of(l);
        } else if (o instanceof Double d) {
            return Value.of(d);
        } else if (o instanceof Boolean b) {
            return Value.of(b);
        } else if (o instanceof String s) {
            return Value.of(s);
        } else if (o instanceof byte[] bs) {
            return Value.ofBytes(bs);
        } else if (o instanceof double[] ds) {
            return Value.ofDoubles(ds);
        } else if (o instanceof Number n) {
            return Value.of(n.longValue());
        }
        throw new IllegalArgumentException("a " + (o == null ? "null" : o.getClass().getName())
                + " is not a value of type " + List.of(ValueType.values()));
    }

    @Override
    public void close() {
        runtime.close();
        HostRecording last;
        synchronized (this) {
            last = recording;
        }
        if (last != null) {
            endRun(last.run().id());
        }
    }
}

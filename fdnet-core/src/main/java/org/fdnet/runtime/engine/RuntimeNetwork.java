package org.fdnet.runtime.engine;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Function;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkCommand;
import org.fdnet.netinfo.ConnectionKind;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.ModuleTree;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeListener;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Controller;
import org.fdnet.runtime.Data;
import org.fdnet.runtime.DataValueObserver;
import org.fdnet.runtime.NetworkEdit;
import org.fdnet.runtime.NodeLifecycle;
import org.fdnet.runtime.Relation;
import org.fdnet.runtime.RelationStatus;
import org.fdnet.runtime.RemoteLink;
import org.fdnet.runtime.SensorData;
import org.fdnet.runtime.ServantRegistry;
import org.fdnet.runtime.Servants;
import org.fdnet.runtime.Value;
import org.fdnet.runtime.WholeNetwork;
import org.fdnet.runtime.loading.NodeClassResolver;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A running network on this host. Its structure always matches a definition ({@link NetworkInfo}), the
 * set of loaded modules and the {@link Placement}: every structural request edits a copy of the
 * definition, {@link StructurePlan plans} what must run, constructs every new node (refusing the request,
 * with nothing changed, if one cannot be made), and then — under the structure lock — commits: drops
 * links, destroys and creates nodes, makes links, rewires Relations, reports statuses, and finally, after
 * the lock, asks the Relations that start or were rewired to fire. Firings never take the structure lock,
 * so a Relation may reshape the network from {@code compute} (its Servants) without deadlock.
 */
public final class RuntimeNetwork implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(RuntimeNetwork.class);

    private final RuntimeOptions options;
    private final EventPublisher events;
    private final Dataflow flow;
    private final Scheduler scheduler;
    /** {@code null} on a driven clock. */
    private final ScheduledExecutorService timer;
    /** Simulated time, or {@code null} on the wall clock. */
    private final DrivenClock driven;
    private final NodeClassResolver resolver;
    private final NodeFactory factory;
    private final ReentrantLock structure = new ReentrantLock();
    private final List<ChangeListener> listeners = new CopyOnWriteArrayList<>();
    private final Map<NodeRef, Integer> ids = new ConcurrentHashMap<>();
    private final AtomicInteger nextId = new AtomicInteger(1);
    private final Map<NodeRef, DataNode> datas = new ConcurrentHashMap<>();
    private final Map<NodeRef, RelationNode> relations = new ConcurrentHashMap<>();
    private final Map<Integer, Controller> controllers = new ConcurrentHashMap<>();
    /** Value observers by Data name: they follow the Data through unloads, reloads and parameter changes. */
    private final Map<NodeRef, List<DataValueObserver>> observers = new ConcurrentHashMap<>();

    // guarded by structure
    private NetworkInfo definition;
    private Set<String> loaded = new LinkedHashSet<>();
    private Set<String> held = new LinkedHashSet<>();
    private Set<LiveLink> links = new LinkedHashSet<>();
    private volatile List<RemoteLink> remoteLinks = List.of();
    private volatile boolean closed;
    private volatile WholeNetwork wholeNetwork;
    private final ServantRegistry servantRegistry = new ServantRegistry(() -> wholeNetwork);

    private RuntimeNetwork(NetworkInfo definition, RuntimeOptions options) {
        options.seal();
        this.options = options;
        this.events = new EventPublisher(options.clock());
        options.sinks().forEach(events::add);
        this.driven = options.drivenClock();
        this.flow = new Dataflow(events, driven);
        if (driven == null) {
            this.scheduler = new Scheduler(flow, options.workerThreads(), options.drainBudget(),
                    options.inlineCallers(), options.workerStart());
            this.timer = Executors.newSingleThreadScheduledExecutor(r -> {
                Thread t = new Thread(r, "fdnet-period");
                t.setDaemon(true);
                return t;
            });
        } else {
            // simulated time: no threads of its own; the driver's thread runs every firing
            this.scheduler = new Scheduler(flow, 0, options.drainBudget(), true, options.workerStart());
            this.timer = null;
        }
        flow.attach(scheduler);
        this.resolver = new NodeClassResolver(options.classLoading(), Data.class, Relation.class);
        this.factory = new NodeFactory(resolver, flow);
        this.definition = new NetworkInfo(definition.name());
    }

    /**
     * Starts {@code definition} (copied): modules marked {@code loadatstart} are loaded (nested ones when their parent
     * is, {@link ModuleTree#atStart}).
     *
     * @throws RuntimeStartException listing every node that cannot be made; nothing keeps running
     */
    public static RuntimeNetwork start(NetworkInfo definition, RuntimeOptions options) throws RuntimeStartException {
        RuntimeNetwork network = new RuntimeNetwork(definition, options);
        network.flow.servants(network::servantsOf);
        Set<String> atStart = ModuleTree.atStart(definition);
        NetworkInfo copy = definition.copy();
        List<NetworkCommandDraft> loads = atStart.stream()
                .map(m -> new NetworkCommandDraft(NetworkCommand.LOAD, m)).toList();
        ChangeOutcome outcome = network.change("start " + (definition.name() == null ? "network" : definition.name()),
                EventPublisher.CONTROLLER, n -> replaceAll(n, copy), atStart, Set.of(), Set.of(), loads);
        if (!outcome.executed()) {
            network.close();
            throw new RuntimeStartException(Arrays.asList(outcome.reason().split("\n")));
        }
        return network;
    }

    private static void replaceAll(NetworkInfo target, NetworkInfo source) {
        for (ModuleInfo m : source.modules()) {
            if (!m.isMain()) {
                target.addModule(m.name(), m.loadAtStart());
            }
            for (NodeInfo n : m.nodes()) {
                target.addNode(m.name(), n);
            }
        }
        for (ModuleInfo m : source.modules()) {
            for (var c : m.connections()) {
                target.addConnection(m.name(), c);
            }
        }
    }

    /** The controller of this network (events it causes name source 0, the controller). */
    public Controller controller() {
        return controllerFor(EventPublisher.CONTROLLER);
    }

    /** A controller whose structural events name {@code sourceId} as their source (a Relation using Servants). */
    public Controller controllerFor(int sourceId) {
        return controllers.computeIfAbsent(sourceId, id -> new NetworkController(this, id));
    }

    private Servants servantsOf(RelationNode node) {
        return EngineServants.of(this, node.ref, node.id, wholeNetwork,
                () -> node.alive && node.status != RelationStatus.FAILED && relations.get(node.ref) == node);
    }

    /** This engine's servant tree, servant classes and messages (thesis Appendix 2). */
    public ServantRegistry servantRegistry() {
        return servantRegistry;
    }

    /**
     * From now on, the Servants of this engine's Relations see and reshape {@code whole} (the network over every
     * host this engine runs a share of) instead of this engine alone; {@code null} goes back to this engine.
     */
    public void seeWholeNetwork(WholeNetwork whole) {
        this.wholeNetwork = whole;
    }

    public void addSink(EventSink sink) {
        events.add(sink);
    }

    public void removeSink(EventSink sink) {
        events.remove(sink);
    }

    /**
     * The running instance of a Data, e.g. a {@link SensorData} a driver pushes into; {@code null} when the
     * Data is not running here. A new instance replaces it when its module reloads or its parameters change.
     *
     * @throws IllegalArgumentException when the instance is not a {@code type}
     */
    public <T extends Data> T dataInstance(NodeRef ref, Class<T> type) {
        DataNode d = dataNode(ref);
        if (d == null) {
            return null;
        }
        if (!type.isInstance(d.data)) {
            throw new IllegalArgumentException(ref + " is a " + d.data.getClass().getName() + ", not a " + type.getName());
        }
        return type.cast(d.data);
    }

    /** Reads the current definition under the structure lock (no copy): for Servants and queries. */
    public <T> T readDefinition(Function<NetworkInfo, T> reader) {
        structure.lock();
        try {
            return reader.apply(definition);
        } finally {
            structure.unlock();
        }
    }

    /** Waits until no Relation is queued or running; true if that happened within the timeout. */
    public boolean awaitQuiet(long timeout, TimeUnit unit) throws InterruptedException {
        return flow.awaitQuiet(timeout, unit);
    }

    /** Total firings and Data writes since start. */
    public long firings() {
        return flow.firings();
    }

    public long writes() {
        return flow.writes();
    }

    public int workerThreads() {
        return scheduler.threads();
    }

    /**
     * Runs {@code threads} worker threads from now on (a host's engine sized for the run deployed on it): the
     * missing ones start at once, extra ones stop after the Relations they are running.
     *
     * @throws IllegalArgumentException when {@code threads} is below 1
     * @throws IllegalStateException on a driven clock (no worker threads)
     */
    public void resizeWorkers(int threads) {
        scheduler.resize(threads);
    }

    // ------------------------------------------------------------------ change requests

    record NetworkCommandDraft(NetworkCommand command, String module) {
    }

    /**
     * The one way the structure changes. {@code nextLoaded}/{@code nextHeld} may be null for "as now".
     * Modules that no longer exist drop out of both; {@code main} is always loaded.
     */
    ChangeOutcome change(String description, int source, NetworkEdit edit, Set<String> nextLoaded,
                         Set<String> nextHeld, Set<NodeRef> restart, List<NetworkCommandDraft> moduleCommands) {
        Set<RelationNode> toRequest = new LinkedHashSet<>();
        List<SensorData> toStart = new ArrayList<>();
        ChangeOutcome outcome;
        structure.lock();
        try {
            if (closed) {
                return settle(ChangeOutcome.failed(description, "the network is stopped"));
            }
            NetworkInfo candidate = definition.copy();
            if (edit != null) {
                edit.applyTo(candidate);
            }
            Set<String> loadedNext = new LinkedHashSet<>(nextLoaded == null ? loaded : nextLoaded);
            loadedNext.add(ModuleInfo.MAIN);
            loadedNext.removeIf(m -> candidate.module(m) == null);
            Set<String> heldNext = new LinkedHashSet<>(nextHeld == null ? held : nextHeld);
            heldNext.retainAll(loadedNext);
            StructurePlan plan = StructurePlan.of(candidate, loadedNext, options.placement());
            Prepared prepared = prepare(plan, restart);
            commit(source, candidate, loadedNext, heldNext, plan, prepared, moduleCommands, toRequest, toStart);
            outcome = ChangeOutcome.executed(description);
        } catch (EditRefusedException | IllegalArgumentException e) {
            outcome = ChangeOutcome.failed(description, e.getMessage());
        } finally {
            structure.unlock();
        }
        for (SensorData s : toStart) {
            try {
                NodeLifecycle.start(s);
            } catch (RuntimeException e) {
                LOG.warn("sensor {} failed to start", s, e);
            }
        }
        for (RelationNode r : toRequest) {
            flow.request(r);
        }
        return settle(outcome);
    }

    /**
     * Whether {@code edit} could be applied now, checked as a change checks it — the edit on a copy of the
     * definition, then every node it would start constructed and initialised — without changing anything: the new
     * instances are dropped. The first phase of a change prepared on several hosts before any of them commits.
     *
     * @param loadAddedModules whether the modules the edit adds will be loaded with it (their nodes are checked too)
     * @return {@code null}, or the reason the change would be refused
     */
    public String check(NetworkEdit edit, boolean loadAddedModules) {
        structure.lock();
        try {
            if (closed) {
                return "the network is stopped";
            }
            NetworkInfo candidate = definition.copy();
            edit.applyTo(candidate);
            Set<String> loadedNext = new LinkedHashSet<>(loaded);
            loadedNext.add(ModuleInfo.MAIN);
            if (loadAddedModules) {
                candidate.modules().stream().filter(m -> definition.module(m.name()) == null)
                        .forEach(m -> loadedNext.add(m.name()));
            }
            loadedNext.removeIf(m -> candidate.module(m) == null);
            Prepared prepared = prepare(StructurePlan.of(candidate, loadedNext, options.placement()), Set.of());
            for (Relation r : prepared.relations().values()) {
                try {
                    NodeLifecycle.close(r);
                } catch (RuntimeException e) {
                    LOG.warn("a Relation made only to check a change did not close cleanly", e);
                }
            }
            return null;
        } catch (EditRefusedException | IllegalArgumentException e) {
            return e.getMessage();
        } finally {
            structure.unlock();
        }
    }

    private ChangeOutcome settle(ChangeOutcome outcome) {
        if (!outcome.executed()) {
            LOG.info("change refused: {}", outcome);
        }
        for (ChangeListener l : listeners) {
            try {
                l.changeSettled(outcome);
            } catch (RuntimeException e) {
                LOG.warn("change listener {} failed", l, e);
            }
        }
        return outcome;
    }

    /** New instances for every node to create or replace, made before anything changes. */
    private record Prepared(Map<NodeRef, NodeFactory.PreparedData> datas, Map<NodeRef, Relation> relations,
                            Map<NodeRef, String> brokenStandIns) {
    }

    private Prepared prepare(StructurePlan plan, Set<NodeRef> restart) {
        Map<NodeRef, NodeFactory.PreparedData> newDatas = new LinkedHashMap<>();
        Map<NodeRef, Relation> newRelations = new LinkedHashMap<>();
        Map<NodeRef, String> broken = new HashMap<>();
        List<String> problems = new ArrayList<>();
        for (Map.Entry<NodeRef, NodeInfo> e : plan.local.entrySet()) {
            NodeRef ref = e.getKey();
            NodeInfo info = e.getValue();
            try {
                if (info.kind() == NodeKind.DATA) {
                    DataNode live = datas.get(ref);
                    if (live == null || live.standIn || !live.info.equals(info) || restart.contains(ref)) {
                        refuseFixedParameterChange(ref, live == null || live.standIn ? null : live.info,
                                live == null ? null : live.data, info);
                        newDatas.put(ref, factory.prepareData(ref, info));
                    }
                } else {
                    RelationNode live = relations.get(ref);
                    if (live == null || !live.info.equals(info) || restart.contains(ref)) {
                        refuseFixedParameterChange(ref, live == null ? null : live.info,
                                live == null ? null : live.relation, info);
                        newRelations.put(ref, factory.prepareRelation(ref, info));
                    }
                }
            } catch (NodeFactory.NodeFailure | EditRefusedException failure) {
                problems.add(failure.getMessage());
            } catch (RuntimeException failure) {
                problems.add(ref + " (" + info.className() + "): " + failure);
            }
        }
        for (Map.Entry<NodeRef, NodeInfo> e : plan.standIns.entrySet()) {
            DataNode live = datas.get(e.getKey());
            if (live == null || !live.standIn || !live.info.equals(e.getValue())) {
                try {
                    newDatas.put(e.getKey(), factory.prepareData(e.getKey(), e.getValue()));
                } catch (NodeFactory.NodeFailure | RuntimeException failure) {
                    broken.put(e.getKey(), failure.getMessage());
                }
            }
        }
        if (!problems.isEmpty()) {
            throw new EditRefusedException(String.join("\n", problems));
        }
        return new Prepared(newDatas, newRelations, broken);
    }

    /** A running node's change that touches a parameter its class does not declare live is refused. */
    private static void refuseFixedParameterChange(NodeRef ref, NodeInfo running, Object instance, NodeInfo next) {
        if (running != null && instance != null) {
            String refusal = LiveParameterGate.refusal(ref, running, instance.getClass(), next);
            if (refusal != null) {
                throw new EditRefusedException(refusal);
            }
        }
    }

    private void commit(int source, NetworkInfo candidate, Set<String> loadedNext, Set<String> heldNext,
                        StructurePlan plan, Prepared prepared, List<NetworkCommandDraft> moduleCommands,
                        Set<RelationNode> toRequest, List<SensorData> toStart) {
        for (NetworkCommandDraft c : moduleCommands) {
            events.command(source, c.command(), c.module(), "module");
        }
        Set<LiveLink> wanted = new LinkedHashSet<>();
        for (LiveLink l : plan.links) {
            if (!prepared.brokenStandIns().containsKey(l.data())) {
                wanted.add(l);
            }
        }
        // links that go: gone from the plan, or one of their ends is replaced
        for (LiveLink l : links) {
            boolean replaced = prepared.datas().containsKey(l.data()) || prepared.relations().containsKey(l.relation());
            if (!wanted.contains(l) || replaced) {
                events.command(source, NetworkCommand.DISCONNECT, linkId(l), linkType(l));
            }
        }
        Map<NodeRef, DataNode> removed = destroyNodes(source, plan, prepared);
        createNodes(source, plan, prepared, removed, toRequest, toStart);
        for (LiveLink l : wanted) {
            boolean replaced = prepared.datas().containsKey(l.data()) || prepared.relations().containsKey(l.relation());
            if (!links.contains(l) || replaced) {
                events.command(source, NetworkCommand.CONNECT, linkId(l), linkType(l));
            }
        }
        links = wanted;
        definition = candidate;
        loaded = loadedNext;
        held = heldNext;
        Rewiring.apply(relations.values(), datas, links, held, plan, toRequest, events);
        remoteLinks = remoteLinksOf(plan, prepared.brokenStandIns());
        // Periods start only now: a timer started before the wiring is committed can fire a Relation
        // that does not see its inputs yet, which then fails ("reads 0 inputs").
        for (NodeRef ref : prepared.relations().keySet()) {
            startPeriod(relations.get(ref));
        }
    }

    private void startPeriod(RelationNode node) {
        if (node != null && node.periodMillis > 0 && driven != null) {
            node.nextDueMicros = driven.micros() + node.periodMillis * 1000L;
        } else if (node != null && node.periodMillis > 0) {
            node.periodic = timer.scheduleAtFixedRate(() -> {
                node.periodDue.set(true);
                flow.requestOnPool(node);
            }, node.periodMillis, node.periodMillis, TimeUnit.MILLISECONDS);
        }
    }

    /** Destroys what the plan no longer wants or replaces; returns the Datas removed. */
    private Map<NodeRef, DataNode> destroyNodes(int source, StructurePlan plan, Prepared prepared) {
        Map<NodeRef, DataNode> removed = new HashMap<>();
        for (RelationNode r : List.copyOf(relations.values())) {
            if (!plan.local.containsKey(r.ref) || prepared.relations().containsKey(r.ref)) {
                relations.remove(r.ref);
                r.alive = false;
                if (r.periodic != null) {
                    r.periodic.cancel(false);
                }
                if (r.status != RelationStatus.FAILED) {
                    r.status = RelationStatus.STOPPED;
                    closeQuietly(r);
                }
                events.command(source, NetworkCommand.DESTROY, Integer.toString(r.id), "proc");
            }
        }
        for (DataNode d : List.copyOf(datas.values())) {
            boolean wantedHere = d.standIn ? plan.standIns.containsKey(d.ref) : plan.local.containsKey(d.ref);
            if (!wantedHere || prepared.datas().containsKey(d.ref)) {
                datas.remove(d.ref);
                removed.put(d.ref, d);
                retire(d);
                if (!d.standIn) {
                    events.command(source, NetworkCommand.DESTROY, Integer.toString(d.id), "data");
                }
            }
        }
        return removed;
    }

    private void createNodes(int source, StructurePlan plan, Prepared prepared, Map<NodeRef, DataNode> removed,
                             Set<RelationNode> toRequest, List<SensorData> toStart) {
        for (Map.Entry<NodeRef, NodeFactory.PreparedData> e : prepared.datas().entrySet()) {
            NodeRef ref = e.getKey();
            boolean standIn = plan.standIns.containsKey(ref);
            NodeInfo info = standIn ? plan.standIns.get(ref) : plan.local.get(ref);
            int id = idOf(ref);
            DataNode node = factory.dataNode(id, ref, info, e.getValue(), standIn);
            for (DataValueObserver o : observers.getOrDefault(ref, List.of())) {
                node.addObserver(o);
            }
            // a Data re-made by a parameter change keeps its value unless its type or initial value changed
            DataNode old = removed.get(ref);
            Value first = e.getValue().initial();
            if (old != null && old.type == node.type && old.value != null
                    && java.util.Objects.equals(old.info.parameter("initial"), info.parameter("initial"))) {
                first = old.value;
            }
            // a stand-in is named (so connection events about it resolve) but never "created": its host creates it
            events.named(id, NodeKind.DATA, ref);
            if (!standIn) {
                events.command(source, NetworkCommand.CREATE, Integer.toString(id), "data");
            }
            flow.initialize(node, first);
            datas.put(ref, node);
            if (node.data instanceof SensorData s) {
                toStart.add(s);
            }
        }
        for (Map.Entry<NodeRef, Relation> e : prepared.relations().entrySet()) {
            NodeRef ref = e.getKey();
            int id = idOf(ref);
            RelationNode node = factory.relationNode(id, ref, plan.local.get(ref), e.getValue());
            events.named(id, NodeKind.RELATION, ref);
            events.command(source, NetworkCommand.CREATE, Integer.toString(id), "proc");
            relations.put(ref, node);
            toRequest.add(node);
        }
    }

    private List<RemoteLink> remoteLinksOf(StructurePlan plan, Map<NodeRef, String> broken) {
        List<RemoteLink> result = new ArrayList<>();
        for (StructurePlan.RemoteDraft d : plan.remote) {
            String problem = d.remoteEnd().equals("data") ? broken.get(d.connection().data()) : null;
            if (problem != null) {
                LOG.warn("{} cannot be made here: {}", d.connection(), problem);
            }
            result.add(new RemoteLink(d.connection(), d.remoteEnd(), d.host(), d.remoteEnd().equals("data"), problem));
        }
        return List.copyOf(result);
    }

    private int idOf(NodeRef ref) {
        return ids.computeIfAbsent(ref, k -> nextId.getAndIncrement());
    }

    private String linkId(LiveLink l) {
        return idOf(l.data()) + ">" + idOf(l.relation());
    }

    private static String linkType(LiveLink l) {
        return l.kind() == ConnectionKind.READER ? "reader" : "writer";
    }

    private static void closeQuietly(RelationNode r) {
        try {
            NodeLifecycle.close(r.relation);
        } catch (RuntimeException e) {
            LOG.warn("{}: close failed", r.ref, e);
        }
    }

    private static void stopQuietly(SensorData s) {
        try {
            NodeLifecycle.stop(s);
        } catch (RuntimeException e) {
            LOG.warn("sensor {} failed to stop", s, e);
        }
    }

    // ------------------------------------------------------------------ queries for the controller

    Set<String> loaded() {
        return readDefinition(d -> java.util.Collections.unmodifiableSet(new LinkedHashSet<>(loaded)));
    }

    Set<String> held() {
        return readDefinition(d -> java.util.Collections.unmodifiableSet(new LinkedHashSet<>(held)));
    }

    DataNode dataNode(NodeRef ref) {
        DataNode d = datas.get(ref);
        return d == null || !d.alive ? null : d;
    }

    RelationNode relationNode(NodeRef ref) {
        return relations.get(ref);
    }

    /** Running Relations in definition order. */
    List<RelationNode> relationsInOrder() {
        return readDefinition(def -> {
            List<RelationNode> result = new ArrayList<>();
            for (ModuleInfo m : def.modules()) {
                for (NodeInfo n : m.nodes()) {
                    RelationNode r = relations.get(new NodeRef(m.name(), n.name()));
                    if (r != null) {
                        result.add(r);
                    }
                }
            }
            return result;
        });
    }

    void write(NodeRef ref, Value value) {
        DataNode d = dataNode(ref);
        if (d == null) {
            throw new IllegalArgumentException(ref + " is not a Data running here");
        }
        flow.write(d, value, null);
    }

    AutoCloseable observe(NodeRef ref, DataValueObserver observer) {
        observers.computeIfAbsent(ref, k -> new CopyOnWriteArrayList<>()).add(observer);
        DataNode d = datas.get(ref);
        if (d != null) {
            d.addObserver(observer);
        }
        return () -> {
            List<DataValueObserver> list = observers.get(ref);
            if (list != null) {
                list.remove(observer);
            }
            DataNode current = datas.get(ref);
            if (current != null) {
                current.removeObserver(observer);
            }
        };
    }

    int idIfKnown(NodeRef ref) {
        Integer id = ids.get(ref);
        return id == null ? -1 : id;
    }

    List<RemoteLink> remoteLinks() {
        return remoteLinks;
    }

    NetworkInfo definitionCopy() {
        return readDefinition(NetworkInfo::copy);
    }

    /**
     * On a driven clock: moves simulated time to {@code micros}, firing every period that falls due on the
     * way in time order (Relations due at the same instant in the order they were created), each followed by
     * everything it causes; returns when the network is quiet at {@code micros}. Runs on the caller's thread;
     * call it from one thread (the driver).
     *
     * @throws IllegalStateException on the wall clock, or when the network is closed
     * @throws IllegalArgumentException when {@code micros} lies before the clock's time
     */
    public void advanceTo(long micros) {
        if (driven == null) {
            throw new IllegalStateException("advanceTo needs a network started with RuntimeOptions.drivenClock;"
                    + " this one runs on the wall clock");
        }
        if (closed) {
            throw new IllegalStateException("the network is closed");
        }
        if (micros < driven.micros()) {
            throw new IllegalArgumentException("advanceTo(" + micros + " µs) lies before the driven clock's "
                    + driven.micros() + " µs");
        }
        scheduler.runQueuedHere();
        List<RelationNode> due = new ArrayList<>();
        while (true) {
            long next = Long.MAX_VALUE;
            for (RelationNode r : relations.values()) {
                if (r.periodMillis > 0 && r.alive && r.nextDueMicros > 0 && r.nextDueMicros < next) {
                    next = r.nextDueMicros;
                }
            }
            if (next > micros) {
                break;
            }
            driven.set(next);
            due.clear();
            for (RelationNode r : relations.values()) {
                if (r.periodMillis > 0 && r.alive && r.nextDueMicros == next) {
                    due.add(r);
                }
            }
            due.sort(java.util.Comparator.comparingInt(r -> r.id));
            for (RelationNode r : due) {
                r.nextDueMicros += r.periodMillis * 1000L;
                r.periodDue.set(true);
                flow.request(r);
                scheduler.runQueuedHere();
            }
        }
        driven.set(micros);
        scheduler.runQueuedHere();
    }

    /** The driven clock's time, µs; on the wall clock the wall time. */
    public long timeMicros() {
        return flow.wallMicros();
    }

    void addListener(ChangeListener l) {
        listeners.add(l);
    }

    void removeListener(ChangeListener l) {
        listeners.remove(l);
    }

    /** Stops the network: no more firings; every node closes; sinks are flushed (not closed: the caller owns them). */
    @Override
    public void close() {
        structure.lock();
        try {
            if (closed) {
                return;
            }
            closed = true;
        } finally {
            structure.unlock();
        }
        if (timer != null) {
            timer.shutdownNow();
        }
        scheduler.close();
        servantRegistry.close();
        for (RelationNode r : relations.values()) {
            r.alive = false;
            if (r.status != RelationStatus.FAILED) {
                r.status = RelationStatus.STOPPED;
                closeQuietly(r);
            }
        }
        for (DataNode d : datas.values()) {
            retire(d);
        }
        events.flush();
        resolver.close();
    }

    /** A Data leaves: no more writes, its sensor stops, its resources close. */
    private static void retire(DataNode d) {
        d.alive = false;
        if (d.data instanceof SensorData s) {
            stopQuietly(s);
        }
        try {
            NodeLifecycle.close(d.data);
        } catch (RuntimeException e) {
            LOG.warn("{}: close failed", d.ref, e);
        }
    }
}

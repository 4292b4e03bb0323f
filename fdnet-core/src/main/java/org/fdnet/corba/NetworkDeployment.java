package org.fdnet.corba;

import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.locks.ReentrantLock;
import java.util.function.Supplier;
import java.util.stream.Collectors;
import org.fdnet.corba.idl.ConnectionSpec;
import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.NetworkCoordinator;
import org.fdnet.corba.idl.NodeSpec;
import org.fdnet.corba.idl.Refused;
import org.fdnet.corba.idl.UnknownNode;
import org.fdnet.event.EventClock;
import org.fdnet.event.EventSink;
import org.fdnet.event.NetworkCommand;
import org.fdnet.event.NetworkCommandEvent;
import org.omg.CORBA.SystemException;
import org.omg.CORBA.UserException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A network spread over hosts by the coordinating process ({@code fdnet run}): it creates each host's
 * share of a {@link DeploymentPlan}, opens the links, then watches the hosts.
 *
 * <pre>
 *   deploy:  per host: createStandIn(remote Datas its Relations touch) → loadModule(nodes + connections)
 *            per link: receiver.acceptLink → sender.forward (batched, windowed, in order)
 *   watch:   every pingMillis: host.ping()
 *            fails          → host LOST: its links BROKEN (listener + NetworkCommandEvent disconnect/link)
 *            registers again (new incarnation) → re-create its share, re-accept its links, re-point the
 *                             senders at it (they resend what it never acknowledged) → links restored
 * </pre>
 *
 * The other hosts run on while one is lost: values bound for it wait in their links (up to the link
 * capacity) and arrive, in order, once it is back.
 */
public final class NetworkDeployment implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(NetworkDeployment.class);

    private volatile DeploymentPlan plan; // replaced by structural changes (DistributedControl)
    private final HostDirectory directory;
    private final DeploymentListener listener;
    private final EventSink events;
    private final EventClock clock = new EventClock();
    private final int window;
    private final Map<String, Host> hosts = new ConcurrentHashMap<>();
    private final Map<String, Long> incarnations = new ConcurrentHashMap<>();
    private final Map<String, Long> lostSince = new ConcurrentHashMap<>();
    private final Set<Long> brokenLinks = ConcurrentHashMap.newKeySet();
    private final Map<String, Long> recoveryMillis = new ConcurrentHashMap<>();
    private final ScheduledExecutorService watcher;

    private RunRecording recording; // set once, before the first share is deployed
    private final Map<String, String> commitReports = new ConcurrentHashMap<>();
    private final Map<String, Integer> workerThreads = new ConcurrentHashMap<>();
    private final Map<String, Long> clockOffsets = new ConcurrentHashMap<>();
    private volatile NetworkCoordinator coordinator;
    /** Held by every change of the running network and while a lost host's share is re-created. */
    private final ReentrantLock changes = new ReentrantLock();

    private NetworkDeployment(DeploymentPlan plan, HostDirectory directory, DeploymentListener listener,
                              EventSink events, int window) {
        this.plan = plan;
        this.directory = directory;
        this.listener = listener;
        this.events = events;
        this.window = window;
        this.watcher = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "fdnet-deployment-watch");
            t.setDaemon(true);
            return t;
        });
    }

    /**
     * Deploys {@code plan}: waits up to {@code hostWaitMillis} for every host to be registered, creates
     * every share and link, and starts watching the hosts every {@code pingMillis}.
     *
     * @param known hosts already at hand (this process's own host), by name
     * @throws DeploymentException naming the host and node that could not be set up; nothing is left half-made
     */
    public static NetworkDeployment start(DeploymentPlan plan, HostDirectory directory, Map<String, Host> known,
                                          DeploymentListener listener, EventSink events, int window,
                                          long hostWaitMillis, long pingMillis) throws DeploymentException {
        return start(plan, directory, known, listener, events, window, hostWaitMillis, pingMillis, null);
    }

    /**
     * As above; when {@code recording} is given, every host is told to record its events as its part of that run
     * before its share is created (and again when it comes back after a restart, or joins), so the logger learns
     * every node's name; {@link #close} ends every host's recording.
     */
    public static NetworkDeployment start(DeploymentPlan plan, HostDirectory directory, Map<String, Host> known,
                                          DeploymentListener listener, EventSink events, int window,
                                          long hostWaitMillis, long pingMillis, RunRecording recording)
            throws DeploymentException {
        NetworkDeployment d = new NetworkDeployment(plan, directory, listener, events, window);
        d.recording = recording;
        d.hosts.putAll(known);
        try {
            d.resolveAll(hostWaitMillis);
            for (String host : plan.hosts()) {
                d.deployShare(host, d.hosts.get(host));
            }
            for (DeploymentPlan.Link link : plan.links()) {
                d.openLink(link);
            }
        } catch (DeploymentException | RuntimeException e) {
            d.undeploy();
            d.watcher.shutdownNow();
            throw e;
        }
        d.watcher.scheduleWithFixedDelay(d::watch, pingMillis, pingMillis, TimeUnit.MILLISECONDS);
        return d;
    }

    private void resolveAll(long waitMillis) throws DeploymentException {
        long deadline = System.currentTimeMillis() + waitMillis;
        for (String name : plan.hosts()) {
            while (!hosts.containsKey(name)) {
                Optional<Host> found = directory.find(name).filter(h -> incarnationOf(h) != null);
                if (found.isPresent()) {
                    hosts.put(name, found.get());
                } else if (System.currentTimeMillis() > deadline) {
                    throw new DeploymentException("host '" + name + "' is not running: no live host of that name in "
                            + directory.where() + " (start it with: fdnet host --name " + name + " --naming "
                            + directory.where() + ")");
                } else {
                    sleep(100);
                }
            }
            incarnations.put(name, incarnationOf(hosts.get(name)));
        }
    }

    private void deployShare(String hostName, Host host) throws DeploymentException {
        DeploymentPlan.HostShare share = plan.shareOf(hostName);
        try {
            welcome(hostName, host);
            for (DeploymentPlan.StandIn s : share.standIns()) {
                host.createStandIn(IdlMapping.spec(s.data().module(), s.node()), s.homeHost());
            }
            // One loadModule per module: its Relations start with their connections in place.
            for (String module : share.modules()) {
                NodeSpec[] nodes = share.nodes().stream().filter(p -> p.module().equals(module))
                        .map(p -> IdlMapping.spec(module, p.node())).toArray(NodeSpec[]::new);
                ConnectionSpec[] connections = share.connections().stream().filter(c -> c.module().equals(module))
                        .map(c -> IdlMapping.spec(c.connection())).toArray(ConnectionSpec[]::new);
                host.loadModule(module, nodes, connections);
            }
        } catch (Refused e) {
            throw new DeploymentException("host '" + hostName + "' refused its share: " + e.reason, e);
        } catch (SystemException e) {
            throw new DeploymentException("host '" + hostName + "' failed while its share was set up: " + e, e);
        }
    }

    /**
     * Tells a host of this network about the run — its engine's worker threads, whether it keeps its events for the
     * trace, the logger to record with — and the coordinator its Servants ask.
     */
    private void welcome(String hostName, Host host) throws Refused {
        if (recording != null) {
            workerThreads.put(hostName, host.sizeEngine(recording.workers()));
            if (recording.traced()) {
                try {
                    host.traceRun(recording.run().id().toString(), recording.traceCapacity());
                } catch (Refused e) {
                    LOG.warn("host {} is not traced: {}", hostName, e.reason); // the run goes on without its lines
                }
            }
            long offset = ClockOffset.of(host);
            clockOffsets.put(hostName, offset);
            if (host.recordRun(recording.loggerAddress(), IdlMapping.description(recording.run()), offset)) {
                LOG.info("host {} records its part of run {}", hostName, recording.run().id());
            }
        }
        NetworkCoordinator c = coordinator;
        if (c != null) {
            host.joinNetwork(c);
        }
    }

    /**
     * Makes {@code coordinator} the one every host's Servants ask about the whole network (and reshape it
     * through): told to every host now, and to every host that joins or comes back later.
     */
    public void introduce(NetworkCoordinator coordinator) {
        this.coordinator = coordinator;
        for (String name : plan.hosts()) {
            Host h = hosts.get(name);
            try {
                if (h != null) {
                    h.joinNetwork(coordinator);
                }
            } catch (SystemException e) {
                LOG.warn("host {} was not told the coordinator: {}", name, e.toString());
            }
        }
    }

    /**
     * A host for a structural change: one of the deployment's, or one registered in the naming service that joins
     * now (told the logger and the coordinator); {@code null} when no live host of that name is registered.
     */
    Host join(String name) {
        Host known = hosts.get(name);
        if (known != null) {
            return known;
        }
        Optional<Host> found;
        try {
            found = directory.find(name).filter(h -> incarnationOf(h) != null);
        } catch (HostUnreachableException e) {
            LOG.warn("naming service unreachable while looking for {}: {}", name, e.getMessage());
            return null;
        }
        if (found.isEmpty()) {
            return null;
        }
        try {
            welcome(name, found.get());
        } catch (Refused | SystemException e) {
            LOG.warn("host {} joins without logger or coordinator: {}", name, e instanceof Refused r ? r.reason : e);
        }
        hosts.put(name, found.get());
        incarnations.put(name, incarnationOf(found.get()));
        return found.get();
    }

    /** The plan after a structural change executed on the hosts: what is watched and re-created from now on. */
    void replacePlan(DeploymentPlan next) {
        this.plan = next;
    }

    /** Closes both ends of a link; an end whose host does not answer is left (it dies with its node). */
    void closeLink(DeploymentPlan.Link link) {
        for (String end : List.of(link.fromHost(), link.toHost())) {
            Host h = hosts.get(end);
            if (h != null) {
                try {
                    h.closeLink(link.id());
                } catch (SystemException e) {
                    LOG.info("could not close {} on {}: {}", link, end, e.toString());
                }
            }
        }
        brokenLinks.remove(link.id());
    }

    void openLink(DeploymentPlan.Link link) throws DeploymentException {
        Host from = hosts.get(link.fromHost());
        Host to = hosts.get(link.toHost());
        try {
            to.acceptLink(link.id(), IdlMapping.id(link.data()), link.fromHost());
            from.forward(link.id(), IdlMapping.id(link.data()), to, link.toHost(), window);
        } catch (UserException | SystemException e) {
            throw new DeploymentException("cannot open " + link + ": " + describe(e), e);
        }
    }

    private void watch() {
        for (String name : plan.hosts()) {
            try {
                if (lostSince.containsKey(name)) {
                    tryRecover(name);
                } else {
                    Long incarnation = incarnationOf(hosts.get(name));
                    if (incarnation == null) {
                        lost(name, "it does not answer");
                    } else if (!incarnation.equals(incarnations.get(name))) {
                        lost(name, "it restarted");
                        tryRecover(name);
                    }
                }
            } catch (RuntimeException e) {
                LOG.warn("watching host {} failed: {}", name, e.toString(), e);
            }
        }
    }

    private void lost(String name, String reason) {
        // Status first (links broken, then the host lost), so a reader never sees a lost host with live links.
        List<DeploymentPlan.Link> newlyBroken = new ArrayList<>();
        for (DeploymentPlan.Link link : plan.linksTouching(name)) {
            if (brokenLinks.add(link.id())) {
                newlyBroken.add(link);
            }
        }
        lostSince.put(name, System.nanoTime());
        LOG.warn("host {} lost: {}", name, reason);
        listener.hostLost(name, reason);
        for (DeploymentPlan.Link link : newlyBroken) {
            events.accept(new NetworkCommandEvent(0, clock.next(), "host", NetworkCommand.DISCONNECT,
                    link.toString(), "link"));
            listener.linkBroken(link, "host " + name + " lost: " + reason);
        }
    }

    /**
     * Runs a change of the running network ({@link DistributedControl}) while no other runs and no lost host is being
     * re-created: a host that comes back is re-created either from the plan before a change or from the plan after it.
     */
    <T> T changingShares(Supplier<T> change) {
        changes.lock();
        try {
            return change.get();
        } finally {
            changes.unlock();
        }
    }

    /**
     * {@link #changingShares} for a change asked by a host's Relation: empty, at once, when another change runs. A
     * Relation a change starts fires on the thread of that change's commit on its host, while the coordinator waits
     * for the commit; were it to wait for the coordinator in turn, neither would ever finish.
     */
    <T> Optional<T> ifNoChangeRuns(Supplier<T> change) {
        if (!changes.tryLock()) {
            return Optional.empty();
        }
        try {
            return Optional.of(change.get());
        } finally {
            changes.unlock();
        }
    }

    private void tryRecover(String name) {
        changingShares(() -> {
            recover(name);
            return null;
        });
    }

    private void recover(String name) {
        Optional<Host> found;
        try {
            found = directory.find(name);
        } catch (HostUnreachableException e) {
            LOG.debug("naming service unreachable while looking for {}: {}", name, e.getMessage());
            return;
        }
        if (found.isEmpty()) {
            return;
        }
        Host host = found.get();
        Long incarnation = incarnationOf(host);
        if (incarnation == null) {
            return; // still the dead host's binding
        }
        long noticed = System.nanoTime();
        try {
            hosts.put(name, host);
            // The same incarnation was only slow to answer: its links heal by themselves (they retry),
            // and re-opening them would restart sequences under values still in flight.
            if (!incarnation.equals(incarnations.get(name))) {
                deployShare(name, host);
                for (DeploymentPlan.Link link : plan.linksTouching(name)) {
                    if (lostSince.containsKey(link.fromHost().equals(name) ? link.toHost() : link.fromHost())) {
                        continue; // the other end is lost too: it is re-wired when it returns
                    }
                    openLink(link);
                }
            }
        } catch (DeploymentException e) {
            LOG.warn("host {} is back but could not be re-wired yet: {}", name, e.getMessage());
            return;
        }
        incarnations.put(name, incarnation);
        long outage = (noticed - lostSince.remove(name)) / 1_000_000;
        long rewire = (System.nanoTime() - noticed) / 1_000_000;
        recoveryMillis.put(name, rewire);
        LOG.info("host {} back after {} ms; re-wired in {} ms", name, outage, rewire);
        listener.hostRecovered(name, outage, rewire);
        for (DeploymentPlan.Link link : plan.linksTouching(name)) {
            boolean otherEndLost = lostSince.containsKey(link.fromHost()) || lostSince.containsKey(link.toHost());
            if (!otherEndLost && brokenLinks.remove(link.id())) {
                events.accept(new NetworkCommandEvent(0, clock.next(), "host", NetworkCommand.CONNECT,
                        link.toString(), "link"));
                listener.linkRestored(link);
            }
        }
    }

    private static Long incarnationOf(Host host) {
        try {
            return host.ping();
        } catch (SystemException e) {
            return null;
        }
    }

    public DeploymentPlan plan() {
        return plan;
    }

    /** Hosts currently lost. */
    public Set<String> lostHosts() {
        return Set.copyOf(lostSince.keySet());
    }

    /** Links currently broken. */
    public List<DeploymentPlan.Link> brokenLinks() {
        return plan.links().stream().filter(l -> brokenLinks.contains(l.id())).collect(Collectors.toList());
    }

    /** The last re-wiring time of each recovered host, in milliseconds. */
    public Map<String, Long> recoveryMillis() {
        return Map.copyOf(recoveryMillis);
    }

    /** The worker threads each host's engine runs for this run, as each said when it was told (empty without a run). */
    public Map<String, Integer> workerThreads() {
        return Map.copyOf(workerThreads);
    }

    /** How far {@code host}'s clock is ahead of this process's, in µs, as measured when it was told the run; 0 unknown. */
    public long clockOffsetMicros(String host) {
        return clockOffsets.getOrDefault(host, 0L);
    }

    /** The run every host was told about, if any. */
    public Optional<RunRecording> recording() {
        return Optional.ofNullable(recording);
    }

    /** The current reference of a host of the plan. */
    public Host host(String name) {
        return hosts.get(name);
    }

    private void undeploy() {
        for (DeploymentPlan.Link link : plan.links()) {
            for (String end : List.of(link.fromHost(), link.toHost())) {
                Host h = hosts.get(end);
                if (h != null) {
                    try {
                        h.closeLink(link.id());
                    } catch (SystemException e) {
                        LOG.debug("could not close {} on {}: {}", link, end, e.toString());
                    }
                }
            }
        }
        for (String name : plan.hosts()) {
            Host h = hosts.get(name);
            if (h == null) {
                continue;
            }
            for (DeploymentPlan.Placed p : plan.shareOf(name).nodes()) {
                try {
                    h.destroyNode(IdlMapping.id(p.ref()));
                } catch (UnknownNode | SystemException e) {
                    LOG.debug("could not destroy {} on {}: {}", p.ref(), name, e.toString());
                }
            }
            for (DeploymentPlan.StandIn s : plan.shareOf(name).standIns()) {
                try {
                    h.destroyNode(IdlMapping.id(s.data()));
                } catch (UnknownNode | SystemException e) {
                    LOG.debug("could not destroy stand-in {} on {}: {}", s.data(), name, e.toString());
                }
            }
        }
    }

    private static String describe(Exception e) {
        if (e instanceof Refused r) {
            return r.reason;
        }
        if (e instanceof UnknownNode u) {
            return "unknown node " + IdlMapping.ref(u.id);
        }
        return e.toString();
    }

    private static void sleep(long millis) {
        try {
            Thread.sleep(millis);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }

    /** Stops watching and removes the network from every reachable host. */
    @Override
    public void close() {
        watcher.shutdownNow();
        undeploy();
        endRecordings();
    }

    /** Each host's recording of the run ends: the host waits (bounded) for the logger's commits and says so. */
    private void endRecordings() {
        if (recording == null) {
            return;
        }
        for (String name : plan.hosts()) {
            Host h = hosts.get(name);
            if (h == null || lostSince.containsKey(name)) {
                continue;
            }
            try {
                String report = h.endRun(recording.run().id().toString());
                if (!report.isEmpty()) {
                    commitReports.put(name, report);
                }
            } catch (SystemException e) {
                LOG.warn("host {} did not end its recording of run {}: {}", name, recording.run().id(), e.toString());
            }
        }
    }

    /** After {@link #close}: what the logger committed of each host's part of the run, by host. */
    public Map<String, String> commitReports() {
        return Map.copyOf(commitReports);
    }
}

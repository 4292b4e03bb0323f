package org.fdnet.corba;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.NoSuchElementException;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import org.fdnet.corba.idl.ChangeKind;
import org.fdnet.corba.idl.ChangeOp;
import org.fdnet.corba.idl.ChangeRequest;
import org.fdnet.corba.idl.ConnectionSpec;
import org.fdnet.corba.idl.HostPOA;
import org.fdnet.corba.idl.NetworkCoordinator;
import org.fdnet.corba.idl.NetworkListener;
import org.fdnet.corba.idl.NodeId;
import org.fdnet.corba.idl.NodeSpec;
import org.fdnet.corba.idl.Refused;
import org.fdnet.corba.idl.RunDescription;
import org.fdnet.corba.idl.ShareChange;
import org.fdnet.corba.idl.TraceBatch;
import org.fdnet.corba.idl.TraceLine;
import org.fdnet.corba.idl.UnknownLink;
import org.fdnet.corba.idl.UnknownNode;
import org.fdnet.corba.idl.UnknownServant;
import org.fdnet.corba.idl.Value;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.corba.idl.ValueSink;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.MessageRefusedException;
import org.fdnet.runtime.ServantRegistry;
import org.fdnet.tls.Right;
import org.omg.CORBA.ORB;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The CORBA servant of one FDNet host ({@code interface Host} of {@code fdnet.idl}): turns remote
 * requests into calls on the host's {@link LocalNetwork} and runs the host's ends of cross-host links.
 *
 * <p>Errors a caller can cause come back as IDL exceptions whose text names the node and the reason; the
 * host keeps serving. Every operation that reveals a value or changes the host first asks {@link Caller} whether the
 * caller's certificate may: values need {@code read} or {@code write} on the Data, structure {@code reshape},
 * {@code load} or {@code unload} on the module, deploying a run ({@link #recordRun}, {@link #sizeEngine},
 * {@link #traceRun}, {@link #joinNetwork}) {@code load} of {@code main}, servant messages {@code reshape} of every
 * module; a refusal is the call's {@code NO_PERMISSION} and nothing of the call is applied. Names, nodes, liveness
 * and structural notices stay open to every member. Links: inbound ends ({@link InboundLink}) by link id; outbound ends
 * ({@link OutboundLink}) observe a local node and push its values to a peer.
 */
public final class HostServant extends HostPOA implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(HostServant.class);

    private final String hostName;
    private final long incarnation;
    private final LocalNetwork network;
    private final ClassPolicy policy;
    private final LinkSettings linkSettings;
    private final ORB orb;
    private final ChangeNotifier notifier;
    private final LiveChanges liveChanges;
    private final ShareChanges shareChanges;
    private final Map<Long, InboundLink> inbound = new ConcurrentHashMap<>();
    private final Map<Long, Forwarding> outbound = new ConcurrentHashMap<>();
    private final AtomicLong retiredReceived = new AtomicLong();
    private final Map<NodeRef, Map<String, AtomicLong>> seenByTarget = new ConcurrentHashMap<>();
    private final ChangeOwners changeOwners;

    private record Forwarding(OutboundLink link, NodeRef source, AutoCloseable observation) {
    }

    public HostServant(String hostName, LocalNetwork network, ClassPolicy policy, LinkSettings linkSettings, ORB orb) {
        this.hostName = hostName;
        this.incarnation = System.currentTimeMillis() * 1000 + (System.nanoTime() & 0x3ff);
        this.network = network;
        this.policy = policy;
        this.linkSettings = linkSettings;
        this.orb = orb;
        this.notifier = new ChangeNotifier(hostName);
        this.liveChanges = new LiveChanges(hostName, network);
        this.shareChanges = new ShareChanges(hostName, network, policy);
        this.changeOwners = new ChangeOwners(hostName);
    }

    @Override
    public String name() {
        return hostName;
    }

    @Override
    public long ping() {
        return incarnation;
    }

    @Override
    public void createNode(NodeSpec spec) throws Refused {
        Caller.require(Right.RESHAPE, spec.id.moduleName);
        NodeInfo node = IdlMapping.node(spec, hostName);
        String refusal = policy.refusal(node);
        if (refusal != null) {
            LOG.warn("refused to create {}: {}", IdlMapping.ref(spec.id), refusal);
            throw new Refused(refusal);
        }
        NodeRef ref = IdlMapping.ref(spec.id);
        refuseOnError(ref, () -> network.create(ref, node));
        notifier.publish(ChangeKind.NODE_CREATED, ref.toString());
    }

    @Override
    public void createStandIn(NodeSpec spec, String homeHost) throws Refused {
        Caller.require(Right.RESHAPE, spec.id.moduleName);
        NodeRef ref = IdlMapping.ref(spec.id);
        refuseOnError(ref, () -> network.createStandIn(ref, IdlMapping.node(spec, homeHost)));
        notifier.publish(ChangeKind.NODE_CREATED, ref + " (stand-in)");
    }

    @Override
    public void destroyNode(NodeId id) throws UnknownNode {
        Caller.require(Right.RESHAPE, id.moduleName);
        NodeRef ref = IdlMapping.ref(id);
        closeLinksOf(ref);
        try {
            network.destroy(ref);
        } catch (NoSuchElementException e) {
            throw new UnknownNode(id);
        }
        notifier.publish(ChangeKind.NODE_DESTROYED, ref.toString());
    }

    @Override
    public boolean recordRun(String address, RunDescription run, long clockOffsetMicros) throws Refused {
        Caller.requireDeploy();
        try {
            return network.recordRun(address, IdlMapping.run(run), clockOffsetMicros);
        } catch (IllegalArgumentException | UnsupportedOperationException e) {
            LOG.warn("host {} refused to record run {} with the logger at {}: {}", hostName, run.id, address,
                    e.getMessage());
            throw new Refused("host " + hostName + " cannot record run " + run.id + " with the logger at " + address
                    + ": " + e.getMessage());
        }
    }

    @Override
    public long clockMicros() {
        return System.currentTimeMillis() * 1000;
    }

    @Override
    public String endRun(String id) {
        Caller.requireDeploy();
        try {
            return network.endRun(java.util.UUID.fromString(id)).orElse("");
        } catch (IllegalArgumentException e) {
            return "";
        }
    }

    @Override
    public int sizeEngine(int workers) throws Refused {
        Caller.requireDeploy();
        try {
            return network.sizeEngine(workers);
        } catch (IllegalArgumentException | IllegalStateException | UnsupportedOperationException e) {
            LOG.warn("host {} refused to run {} worker threads: {}", hostName, workers, e.getMessage());
            throw new Refused("host " + hostName + ": " + e.getMessage());
        }
    }

    @Override
    public void traceRun(String runId, int capacity) throws Refused {
        Caller.requireDeploy();
        try {
            network.traceRun(java.util.UUID.fromString(runId), capacity);
        } catch (IllegalArgumentException | UnsupportedOperationException e) {
            throw new Refused("host " + hostName + " cannot trace run " + runId + ": " + e.getMessage());
        }
    }

    @Override
    public TraceBatch takeTrace(String runId, int max) {
        Caller.requireDeploy();
        HostTrace.Batch batch;
        try {
            batch = network.takeTrace(java.util.UUID.fromString(runId), Math.max(0, max));
        } catch (IllegalArgumentException notARun) {
            batch = HostTrace.Batch.EMPTY;
        }
        TraceLine[] lines = new TraceLine[batch.lines().size()];
        for (int i = 0; i < lines.length; i++) {
            HostTrace.Line l = batch.lines().get(i);
            lines[i] = new TraceLine(l.timeMicros(), l.text());
        }
        return new TraceBatch(lines, batch.dropped());
    }

    @Override
    public void endTrace(String runId) {
        Caller.requireDeploy();
        try {
            network.endTrace(java.util.UUID.fromString(runId));
        } catch (IllegalArgumentException notARun) {
            LOG.debug("host {}: endTrace of {}, which is no run id", hostName, runId);
        }
    }

    @Override
    public String prepareChange(ChangeRequest change) {
        Caller.fail(switch (change.op.value()) {
            case ChangeOp._CO_SEND -> Caller.refusal(Right.WRITE, IdlMapping.ref(change.node));
            case ChangeOp._CO_SET_PARAMETER -> Caller.refusal(Right.RESHAPE, change.node.moduleName);
            default -> Caller.refusal(Right.RESHAPE, change.moduleName);
        });
        String refusal = liveChanges.prepare(change);
        if (!refusal.isEmpty()) {
            LOG.info("host {} refused change {}: {}", hostName, change.id, refusal);
        } else {
            changeOwners.prepared(change.id);
        }
        return refusal;
    }

    @Override
    public String prepareShareChange(ShareChange change) {
        for (String module : ShareChanges.modules(change)) {
            Caller.require(Right.RESHAPE, module);
        }
        String refusal = shareChanges.prepare(change);
        if (!refusal.isEmpty()) {
            LOG.info("host {} refused change {}: {}", hostName, change.id, refusal);
        } else {
            changeOwners.prepared(change.id);
        }
        return refusal;
    }

    @Override
    public void commitChange(long id) throws Refused {
        changeOwners.settle(id, "commit");
        ShareChange structural = shareChanges.take(id);
        if (structural != null) {
            String failure = shareChanges.execute(structural, this::closeLinksOf);
            if (failure != null) {
                LOG.warn("host {}: structural change {} failed: {}", hostName, id, failure);
                throw new Refused(failure);
            }
            for (NodeId gone : structural.destroy) {
                notifier.publish(ChangeKind.NODE_DESTROYED, IdlMapping.ref(gone).toString());
            }
            for (NodeSpec made : structural.create) {
                notifier.publish(ChangeKind.NODE_CREATED, IdlMapping.ref(made.id).toString());
            }
            return;
        }
        String failure = liveChanges.commit(id);
        if (failure != null) {
            throw new Refused(failure);
        }
    }

    @Override
    public void abortChange(long id) {
        changeOwners.settle(id, "abort");
        liveChanges.abort(id);
        shareChanges.abort(id);
    }

    @Override
    public Value answerMessage(String servantPath, String message, Value argument) throws UnknownServant, Refused {
        Caller.requireEveryModule(Right.RESHAPE);
        ServantRegistry servants = network.servants().orElse(null);
        if (servants == null || !servants.answersHere(servantPath)) {
            throw new UnknownServant(servantPath);
        }
        try {
            return ValueCodec.encode(servants.answerHere(servantPath, message, ValueCodec.decodeRuntime(argument)));
        } catch (MessageRefusedException e) {
            throw new Refused("host " + hostName + ": " + e.getMessage());
        } catch (RuntimeException e) {
            LOG.warn("host {}: servant {} failed on message {}", hostName, servantPath, message, e);
            throw new Refused("host " + hostName + ": servant " + servantPath + " failed on " + message + ": " + e);
        }
    }

    @Override
    public void joinNetwork(NetworkCoordinator coordinator) {
        Caller.requireDeploy();
        network.seeWholeNetwork(new CoordinatorView(coordinator, hostName));
        LOG.info("host {}: its Relations' Servants now see the whole network", hostName);
    }

    @Override
    public String[] nodes() {
        return network.nodes().stream().map(NodeRef::toString).toArray(String[]::new);
    }

    @Override
    public void connect(ConnectionSpec spec) throws UnknownNode, Refused {
        Caller.requireReshape(spec);
        ConnectionInfo c = IdlMapping.connection(spec);
        requireKnown(spec.data);
        requireKnown(spec.relation);
        refuseOnError(c.relation(), () -> network.connect(c));
        notifier.publish(ChangeKind.CONNECTED, c.toString());
    }

    @Override
    public void disconnect(ConnectionSpec spec) throws UnknownNode {
        Caller.requireReshape(spec);
        ConnectionInfo c = IdlMapping.connection(spec);
        requireKnown(spec.data);
        requireKnown(spec.relation);
        network.disconnect(c);
        notifier.publish(ChangeKind.DISCONNECTED, c.toString());
    }

    @Override
    public Value read(NodeId data) throws UnknownNode, Refused {
        Caller.require(Right.READ, IdlMapping.ref(data));
        requireNode(data);
        Object v = network.read(IdlMapping.ref(data));
        if (v == null) {
            throw new Refused(IdlMapping.ref(data) + " has no value yet");
        }
        return ValueCodec.encode(v);
    }

    @Override
    public void write(NodeId data, Value v) throws UnknownNode, Refused {
        Caller.require(Right.WRITE, IdlMapping.ref(data));
        requireNode(data);
        NodeRef ref = IdlMapping.ref(data);
        refuseOnError(ref, () -> network.write(ref, ValueCodec.decode(v)));
    }

    @Override
    public void loadModule(String moduleName, NodeSpec[] nodes, ConnectionSpec[] connections) throws Refused {
        Caller.require(Right.LOAD, moduleName);
        List<NodeInfo> infos = new ArrayList<>();
        for (NodeSpec spec : nodes) {
            NodeInfo node = IdlMapping.node(spec, hostName);
            String refusal = policy.refusal(node);
            if (refusal != null) {
                LOG.warn("refused to load module {}: {}", moduleName, refusal);
                throw new Refused("module " + moduleName + " not loaded on " + hostName + ": " + refusal);
            }
            infos.add(node);
        }
        List<ConnectionInfo> conns = new ArrayList<>();
        for (ConnectionSpec c : connections) {
            conns.add(IdlMapping.connection(c));
        }
        try {
            network.load(moduleName, infos, conns);
        } catch (RuntimeException e) {
            LOG.warn("module {} not loaded: {}", moduleName, e.toString());
            throw new Refused("module " + moduleName + " not loaded on " + hostName + ": " + e.getMessage());
        }
        notifier.publish(ChangeKind.MODULE_LOADED, moduleName + " (" + infos.size() + " nodes, "
                + conns.size() + " connections)");
    }

    @Override
    public void unloadModule(String moduleName) {
        Caller.require(Right.UNLOAD, moduleName);
        for (NodeRef ref : network.nodes()) {
            if (ref.module().equals(moduleName)) {
                closeLinksOf(ref);
                try {
                    network.destroy(ref);
                } catch (NoSuchElementException e) {
                    LOG.debug("{} vanished during unload", ref);
                }
            }
        }
        notifier.publish(ChangeKind.MODULE_UNLOADED, moduleName);
    }

    @Override
    public void acceptLink(long link, NodeId target, String fromHost) throws UnknownNode {
        Caller.require(Right.RESHAPE, target.moduleName);
        requireNode(target);
        NodeRef ref = IdlMapping.ref(target);
        Map<String, AtomicLong> seen = seenByTarget.computeIfAbsent(ref, r -> new ConcurrentHashMap<>());
        retire(inbound.put(link, new InboundLink(link, ref, fromHost, network, seen)));
        notifier.publish(ChangeKind.LINK_OPENED, "link " + link + " from " + fromHost + " into " + IdlMapping.ref(target));
    }

    @Override
    public void forward(long link, NodeId source, ValueSink sink, String toHost, int window)
            throws UnknownNode, Refused {
        Caller.require(Right.RESHAPE, source.moduleName);
        requireNode(source);
        NodeRef ref = IdlMapping.ref(source);
        Forwarding existing = outbound.get(link);
        if (existing != null && existing.source.equals(ref)) {
            existing.link.retarget(sink);
            notifier.publish(ChangeKind.LINK_OPENED, "link " + link + " from " + ref + " to " + toHost + " (again)");
            return;
        }
        LinkSettings settings;
        try {
            settings = window > 0 ? linkSettings.withWindow(window) : linkSettings;
        } catch (IllegalArgumentException e) {
            throw new Refused(e.getMessage());
        }
        String description = hostName + ":" + ref + " -> " + toHost + " (link " + link + ")";
        String stream = hostName + "#" + incarnation + "#" + link;
        OutboundLink out = new OutboundLink(link, stream, description, sink, settings, new OutboundLink.StateListener() {
            @Override
            public void broken(OutboundLink l, String reason) {
                notifier.publish(ChangeKind.LINK_BROKEN, l.description() + ": " + reason);
            }

            @Override
            public void restored(OutboundLink l) {
                notifier.publish(ChangeKind.LINK_OPENED, l.description() + " restored");
            }
        });
        AutoCloseable observation = network.observe(ref, (value, fromHost, origin) -> {
            if (!toHost.equals(fromHost)) {
                out.offer(value, origin);
            }
        });
        Forwarding old = outbound.put(link, new Forwarding(out, ref, observation));
        if (old != null) {
            stop(old);
        }
        notifier.publish(ChangeKind.LINK_OPENED, description);
    }

    @Override
    public void closeLink(long link) {
        InboundLink open = inbound.get(link);
        Forwarding sending = outbound.get(link);
        if (open != null) {
            Caller.require(Right.RESHAPE, open.target().module());
        }
        if (sending != null) {
            Caller.require(Right.RESHAPE, sending.source.module());
        }
        InboundLink in = inbound.remove(link);
        retire(in);
        Forwarding out = outbound.remove(link);
        if (out != null) {
            stop(out);
        }
        if (in != null || out != null) {
            notifier.publish(ChangeKind.LINK_CLOSED, "link " + link);
        }
    }

    /**
     * A peer's {@code deliver} and {@code deliverAhead} are read by {@link CheckedValueReader}, not by the generated
     * helper, so that hostile bytes are refused before anything they claim is allocated; every other operation is
     * dispatched as generated.
     */
    @Override
    public org.omg.CORBA.portable.OutputStream _invoke(String method, org.omg.CORBA.portable.InputStream input,
            org.omg.CORBA.portable.ResponseHandler handler) {
        if ("deliverAhead".equals(method)) {
            deliverAhead(CheckedValueReader.batch(input));
            return null;
        }
        if (!"deliver".equals(method)) {
            return super._invoke(method, input, handler);
        }
        ValueBatch batch = CheckedValueReader.batch(input);
        try {
            long next = deliver(batch);
            org.omg.CORBA.portable.OutputStream out = handler.createReply();
            out.write_longlong(next);
            return out;
        } catch (UnknownLink unknown) {
            org.omg.CORBA.portable.OutputStream out = handler.createExceptionReply();
            org.fdnet.corba.idl.UnknownLinkHelper.write(out, unknown);
            return out;
        }
    }

    @Override
    public long deliver(ValueBatch batch) throws UnknownLink {
        InboundLink in = inbound.get(batch.link);
        if (in == null) {
            throw new UnknownLink(batch.link);
        }
        in.requireWriter(Caller.name());
        return in.deliver(batch);
    }

    /**
     * A value sent ahead has no reply to carry a refusal: it is dropped, and the sender learns why from the
     * {@code deliver} that confirms it (an unknown link, a caller that may not write).
     */
    @Override
    public void deliverAhead(ValueBatch batch) {
        try {
            deliver(batch);
        } catch (UnknownLink | org.omg.CORBA.NO_PERMISSION e) {
            LOG.debug("a value sent ahead on link {} was dropped: {}", batch.link, e.toString());
        }
    }

    @Override
    public void subscribe(NetworkListener listener) {
        notifier.subscribe(listener, orb.object_to_string(listener));
    }

    @Override
    public void unsubscribe(NetworkListener listener) {
        notifier.unsubscribe(orb.object_to_string(listener));
    }

    /** Values applied to this host's Datas from links since it started. */
    public long valuesReceived() {
        return retiredReceived.get() + inbound.values().stream().mapToLong(InboundLink::applied).sum();
    }

    private void retire(InboundLink old) {
        if (old != null) {
            retiredReceived.addAndGet(old.applied());
        }
    }

    /** The outbound links of this host, for status and tests. */
    public List<OutboundLink> outboundLinks() {
        return outbound.values().stream().map(Forwarding::link).toList();
    }

    private void closeLinksOf(NodeRef ref) {
        inbound.values().removeIf(in -> {
            if (in.target().equals(ref)) {
                retire(in);
                return true;
            }
            return false;
        });
        outbound.entrySet().removeIf(e -> {
            if (e.getValue().source.equals(ref)) {
                stop(e.getValue());
                return true;
            }
            return false;
        });
    }

    private void stop(Forwarding f) {
        try {
            f.observation.close();
        } catch (Exception e) {
            LOG.warn("could not stop observing {}: {}", f.source, e.toString(), e);
        }
        f.link.close();
    }

    private void requireKnown(NodeId id) throws UnknownNode {
        if (!network.knows(IdlMapping.ref(id))) {
            throw new UnknownNode(id);
        }
    }

    private void requireNode(NodeId id) throws UnknownNode {
        if (!network.nodes().contains(IdlMapping.ref(id))) {
            throw new UnknownNode(id);
        }
    }

    private static void refuseOnError(NodeRef ref, Runnable action) throws Refused {
        try {
            action.run();
        } catch (RuntimeException e) {
            LOG.warn("refused on {}: {}", ref, e.toString());
            throw new Refused(ref + ": " + (e.getMessage() == null ? e.toString() : e.getMessage()));
        }
    }

    @Override
    public void close() {
        outbound.values().forEach(this::stop);
        outbound.clear();
        inbound.clear();
        notifier.close();
    }
}

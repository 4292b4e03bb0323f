package org.fdnet.corba.control;

import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ThreadLocalRandom;
import org.fdnet.control.LiveNetwork;
import org.fdnet.control.LiveNetworkListener;
import org.fdnet.corba.IdlMapping;
import org.fdnet.corba.ValueCodec;
import org.fdnet.corba.idl.ChangeResult;
import org.fdnet.corba.idl.NodeId;
import org.fdnet.corba.idl.RunningNetworkListener;
import org.fdnet.corba.idl.RunningNetworkPOA;
import org.fdnet.corba.idl.SampledValue;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Value;
import org.omg.CORBA.ORB;
import org.omg.CORBA.SystemException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The CORBA servant of a running network's control object ({@code RunningNetwork} in {@code fdnet.idl}): every
 * call goes to a {@link LiveNetwork}, so the same servant serves a run in one process and a run across hosts.
 * Definitions travel as .fdn text and are validated on the way in as every .fdn file is. Each subscribed
 * listener is told on the subscription's own thread; one whose call fails is dropped.
 */
public final class RunningNetworkImpl extends RunningNetworkPOA {
    private static final Logger LOG = LoggerFactory.getLogger(RunningNetworkImpl.class);

    private final LiveNetwork network;
    private final ORB orb;
    private final long incarnation = ThreadLocalRandom.current().nextLong(1, Long.MAX_VALUE);
    private final Map<String, Forwarder> subscribers = new ConcurrentHashMap<>();

    public RunningNetworkImpl(LiveNetwork network, ORB orb) {
        this.network = Objects.requireNonNull(network, "network");
        this.orb = Objects.requireNonNull(orb, "orb");
    }

    @Override
    public String name() {
        return network.name();
    }

    @Override
    public String loggerViewerAddress() {
        return network.loggerViewerAddress().orElse("");
    }

    @Override
    public long ping() {
        return incarnation;
    }

    @Override
    public String snapshot() {
        return NetworkRepository.toText(network.snapshot());
    }

    @Override
    public String[] loadedModules() {
        return network.loadedModules().toArray(String[]::new);
    }

    @Override
    public String[] heldModules() {
        return network.heldModules().toArray(String[]::new);
    }

    @Override
    public ChangeResult applyChange(String baseFdn, String editedFdn, String description) {
        NetworkInfo base;
        NetworkInfo edited;
        try {
            base = NetworkRepository.fromText(baseFdn, "base of '" + description + "'");
            edited = NetworkRepository.fromText(editedFdn, "edited '" + description + "'");
        } catch (NetworkFileException e) {
            return result(ChangeOutcome.failed(description, "not a valid network: " + e.getMessage()));
        }
        return result(guarded(description, () -> network.apply(description, base, edited)));
    }

    @Override
    public ChangeResult load(String moduleName) {
        return result(guarded("load " + moduleName, () -> network.load(moduleName)));
    }

    @Override
    public ChangeResult unload(String moduleName) {
        return result(guarded("unload " + moduleName, () -> network.unload(moduleName)));
    }

    @Override
    public ChangeResult hold(String moduleName) {
        return result(guarded("hold " + moduleName, () -> network.hold(moduleName)));
    }

    @Override
    public ChangeResult resume(String moduleName) {
        return result(guarded("resume " + moduleName, () -> network.resume(moduleName)));
    }

    @Override
    public ChangeResult setParameter(NodeId node, String parameter, String text) {
        NodeRef ref = IdlMapping.ref(node);
        return result(guarded("set " + ref + ":" + parameter + "=" + text,
                () -> network.setParameter(ref, parameter, text)));
    }

    @Override
    public ChangeResult send(NodeId data, String text) {
        NodeRef ref = IdlMapping.ref(data);
        return result(guarded("send " + ref + "=" + text, () -> network.send(ref, text)));
    }

    @Override
    public void subscribe(RunningNetworkListener listener) {
        String key = orb.object_to_string(listener);
        Forwarder f = new Forwarder(key, listener);
        Forwarder old = subscribers.put(key, f);
        if (old != null) {
            old.end();
        }
        f.handle = network.subscribe(f);
        LOG.info("{}: a tool subscribed ({} now)", network.name(), subscribers.size());
    }

    @Override
    public void unsubscribe(RunningNetworkListener listener) {
        Forwarder f = subscribers.remove(orb.object_to_string(listener));
        if (f != null) {
            f.end();
        }
    }

    /** Tells every subscriber that the network stopped ({@code reason}) and forgets them. */
    public void close(String reason) {
        for (Forwarder f : subscribers.values()) {
            subscribers.remove(f.key);
            f.end();
            try {
                f.listener.disconnected(reason);
            } catch (SystemException e) {
                LOG.debug("subscriber already gone: {}", e.toString());
            }
        }
    }

    private interface Change {
        ChangeOutcome run();
    }

    /** A change that throws (a bug, or a network that stopped meanwhile) is a refusal with the reason, not a CORBA error. */
    private ChangeOutcome guarded(String description, Change change) {
        try {
            return change.run();
        } catch (RuntimeException e) {
            LOG.warn("{}: {} failed: {}", network.name(), description, e.toString(), e);
            return ChangeOutcome.failed(description, e.toString());
        }
    }

    static ChangeResult result(ChangeOutcome o) {
        return new ChangeResult(o.description(), o.executed(), o.reason() == null ? "" : o.reason());
    }

    /** One remote listener, fed by its own subscription of the LiveNetwork. */
    private final class Forwarder implements LiveNetworkListener {
        final String key;
        final RunningNetworkListener listener;
        volatile AutoCloseable handle;

        Forwarder(String key, RunningNetworkListener listener) {
            this.key = key;
            this.listener = listener;
        }

        @Override
        public void changeSettled(ChangeOutcome outcome) {
            tell(() -> listener.changeSettled(result(outcome)));
        }

        @Override
        public void valuesSampled(Map<NodeRef, Value> latest) {
            SampledValue[] values = new SampledValue[latest.size()];
            int i = 0;
            for (Map.Entry<NodeRef, Value> e : latest.entrySet()) {
                values[i++] = new SampledValue(IdlMapping.id(e.getKey()), ValueCodec.encode(e.getValue()));
            }
            tell(() -> listener.valuesSampled(values));
        }

        @Override
        public void disconnected(String reason) {
            subscribers.remove(key, this);
            tell(() -> listener.disconnected(reason));
        }

        private void tell(Runnable call) {
            try {
                call.run();
            } catch (SystemException e) {
                LOG.info("{}: a subscribed tool is gone ({}); dropping it", network.name(), e.getClass().getSimpleName());
                subscribers.remove(key, this);
                end();
            }
        }

        void end() {
            AutoCloseable h = handle;
            if (h == null) {
                return;
            }
            try {
                h.close();
            } catch (Exception e) {
                LOG.debug("closing a subscription failed: {}", e.toString());
            }
        }
    }
}

package org.fdnet.corba.control;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ThreadLocalRandom;
import org.fdnet.control.LiveNetwork;
import org.fdnet.control.LiveNetworkListener;
import org.fdnet.corba.Caller;
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
import org.fdnet.tls.Permissions;
import org.fdnet.tls.Right;
import org.fdnet.tls.TransportSecurity;
import org.omg.CORBA.ORB;
import org.omg.CORBA.SystemException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The CORBA servant of a running network's control object ({@code RunningNetwork} in {@code fdnet.idl}): every
 * call goes to a {@link LiveNetwork}, so the same servant serves a run in one process and a run across hosts.
 * Definitions travel as .fdn text and are validated on the way in as every .fdn file is. Each subscribed
 * listener is told on the subscription's own thread; one whose call fails is dropped.
 *
 * <p>The calling tool's certificate ({@link Caller}) needs {@code reshape} on every module an edit changes, {@code
 * load}, {@code unload} or {@code reshape} (hold, resume, parameters) on the module, {@code write} to send a value; a
 * change it may not make is refused with the reason, and nothing changes. A subscriber is sampled only the Datas its
 * certificate may {@code read}.
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
        String refusal = Caller.refusalToEdit(network.snapshot(), edited);
        if (refusal == null) {
            refusal = Caller.refusalToEdit(base, edited);
        }
        if (refusal != null) {
            return refused(description, refusal);
        }
        return result(guarded(description, () -> network.apply(description, base, edited)));
    }

    @Override
    public ChangeResult load(String moduleName) {
        return permitted(Right.LOAD, moduleName, "load " + moduleName, () -> network.load(moduleName));
    }

    @Override
    public ChangeResult unload(String moduleName) {
        return permitted(Right.UNLOAD, moduleName, "unload " + moduleName, () -> network.unload(moduleName));
    }

    @Override
    public ChangeResult hold(String moduleName) {
        return permitted(Right.RESHAPE, moduleName, "hold " + moduleName, () -> network.hold(moduleName));
    }

    @Override
    public ChangeResult resume(String moduleName) {
        return permitted(Right.RESHAPE, moduleName, "resume " + moduleName, () -> network.resume(moduleName));
    }

    @Override
    public ChangeResult setParameter(NodeId node, String parameter, String text) {
        NodeRef ref = IdlMapping.ref(node);
        return permitted(Right.RESHAPE, ref.module(), "set " + ref + ":" + parameter + "=" + text,
                () -> network.setParameter(ref, parameter, text));
    }

    @Override
    public ChangeResult send(NodeId data, String text) {
        NodeRef ref = IdlMapping.ref(data);
        String description = "send " + ref + "=" + text;
        String refusal = Caller.refusal(Right.WRITE, ref);
        return refusal != null ? refused(description, refusal) : result(guarded(description, () -> network.send(ref, text)));
    }

    @Override
    public void subscribe(RunningNetworkListener listener) {
        String key = orb.object_to_string(listener);
        Forwarder f = new Forwarder(key, listener, Caller.name());
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

    /** A change of a module, made when the caller's certificate has {@code right} on it, else refused with why. */
    private ChangeResult permitted(Right right, String module, String description, Change change) {
        String refusal = Caller.refusal(right, module);
        return refusal != null ? refused(description, refusal) : result(guarded(description, change));
    }

    private ChangeResult refused(String description, String refusal) {
        LOG.info("{}: refused {}: {}", network.name(), description, refusal);
        return result(ChangeOutcome.failed(description, refusal + "; nothing changed"));
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
        /** The subscriber's certificate: it is sampled only the Datas that may read. */
        final String reader;
        volatile AutoCloseable handle;

        Forwarder(String key, RunningNetworkListener listener, String reader) {
            this.key = key;
            this.listener = listener;
            this.reader = reader;
        }

        @Override
        public void changeSettled(ChangeOutcome outcome) {
            tell(() -> listener.changeSettled(result(outcome)));
        }

        @Override
        public void valuesSampled(Map<NodeRef, Value> latest) {
            Permissions permissions = TransportSecurity.permissions();
            List<SampledValue> values = new ArrayList<>(latest.size());
            for (Map.Entry<NodeRef, Value> e : latest.entrySet()) {
                NodeRef ref = e.getKey();
                if (permissions.refusal(reader, Right.READ, ref.module(), ref.node()) == null) {
                    values.add(new SampledValue(IdlMapping.id(ref), ValueCodec.encode(e.getValue())));
                }
            }
            if (!values.isEmpty() || latest.isEmpty()) {
                SampledValue[] sampled = values.toArray(SampledValue[]::new);
                tell(() -> listener.valuesSampled(sampled));
            }
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

package org.fdnet.corba.control;

import java.util.LinkedHashMap;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Objects;
import java.util.Optional;
import java.util.Set;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.function.Supplier;
import org.fdnet.control.LiveNetwork;
import org.fdnet.control.LiveNetworkListener;
import org.fdnet.control.NetworkUnreachableException;
import org.fdnet.corba.CheckedValueReader;
import org.fdnet.corba.IdlMapping;
import org.fdnet.corba.OrbRuntime;
import org.fdnet.corba.OrbSettings;
import org.fdnet.corba.ValueCodec;
import org.fdnet.corba.idl.ChangeResult;
import org.fdnet.corba.idl.RunningNetwork;
import org.fdnet.corba.idl.RunningNetworkHelper;
import org.fdnet.corba.idl.RunningNetworkListenerHelper;
import org.fdnet.corba.idl.RunningNetworkListenerPOA;
import org.fdnet.corba.idl.SampledValue;
import org.fdnet.netinfo.EditRefusedException;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.NetworkEdit;
import org.fdnet.runtime.Value;
import org.omg.CORBA.SystemException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A {@link LiveNetwork} in another process, reached through its control object ({@code RunningNetwork}).
 *
 * <pre>
 *   tool ──apply/load/hold/…──▶ RemoteLiveNetwork ══two-way calls══▶ RunningNetworkImpl (the run's process)
 *   LiveNetworkListener ◀── ListenerServant (this process's ORB) ◀══changeSettled / valuesSampled / disconnected══
 *   watchdog: ping every 500 ms while subscribed ──fails──▶ disconnected(reason) to every listener
 * </pre>
 *
 * Every call is bounded by the ORB's reply timeout ({@value #CALL_TIMEOUT_MILLIS} ms; a refused connection fails at
 * once). Once the network cannot be reached, listeners hear {@code disconnected(reason)} once, changes are
 * refused with one message naming the network and its address, and queries throw
 * {@link NetworkUnreachableException} with that message.
 */
public final class RemoteLiveNetwork implements LiveNetwork {
    private static final Logger LOG = LoggerFactory.getLogger(RemoteLiveNetwork.class);
    static final int CALL_TIMEOUT_MILLIS = 10_000;
    static final long WATCH_MILLIS = 500;

    private final OrbRuntime orb;
    private final RunningNetwork remote;
    private final String address;
    private final String name;
    private final long incarnation;
    private final List<ListenerServant> listeners = new CopyOnWriteArrayList<>();
    private final ScheduledExecutorService watchdog;
    private volatile String unreachable;
    private final AtomicBoolean watching = new AtomicBoolean();

    private RemoteLiveNetwork(OrbRuntime orb, RunningNetwork remote, String address, String name, long incarnation) {
        this.orb = orb;
        this.remote = remote;
        this.address = address;
        this.name = name;
        this.incarnation = incarnation;
        this.watchdog = Executors.newSingleThreadScheduledExecutor(r -> {
            Thread t = new Thread(r, "fdnet-attach-watch-" + name);
            t.setDaemon(true);
            return t;
        });
    }

    /**
     * Attaches to a running network: {@code target} is {@code corbaloc::…} or {@code IOR:…}, {@code HOST:PORT} (a run
     * started with {@code --control-port}), or a network's NAME — looked up in {@code ~/.fdnet/run/NAME.ref} (a run on
     * this machine), else in the naming service {@code namingCorbaloc} when one is given.
     *
     * @throws NetworkUnreachableException naming the target when no such network can be reached
     */
    public static RemoteLiveNetwork attach(String target, String namingCorbaloc) {
        Objects.requireNonNull(target, "target");
        OrbSettings settings = OrbSettings.defaults().withCallTimeoutMillis(CALL_TIMEOUT_MILLIS)
                .withBindAddress(callbackAddress(target.matches(".+:[0-9]{1,5}") && !target.startsWith("corba")
                        ? "corbaloc::" + target : target.startsWith("corbaloc:") ? target : namingCorbaloc));
        if (namingCorbaloc != null) {
            settings = settings.withNaming(namingCorbaloc);
        }
        OrbRuntime orb = OrbRuntime.start(settings);
        try {
            String[] where = new String[1];
            RunningNetwork remote = locate(orb, target, namingCorbaloc, where);
            String name;
            long incarnation;
            try {
                name = remote.name();
                incarnation = remote.ping();
            } catch (SystemException e) {
                throw new NetworkUnreachableException("no running network answers at " + where[0] + " ("
                        + reason(e) + ")", e);
            }
            LOG.info("attached to network {} at {}", name, where[0]);
            return new RemoteLiveNetwork(orb, remote, where[0], name, incarnation);
        } catch (RuntimeException e) {
            orb.close();
            throw e;
        }
    }

    /**
     * The address this process's listeners are reached at: 127.0.0.1 for a network on this machine, else the local
     * address of a connection to the network's host (the network calls its subscribers back).
     */
    static String callbackAddress(String corbaloc) {
        java.util.regex.Matcher m = corbaloc == null ? null
                : java.util.regex.Pattern.compile("corbaloc:(?:iiop)?:(?:[0-9.]+@)?([^:/]+):([0-9]+)").matcher(corbaloc);
        if (m == null || !m.find()) {
            return OrbSettings.LOOPBACK;
        }
        String host = m.group(1);
        try {
            java.net.InetAddress address = java.net.InetAddress.getByName(host);
            if (address.isLoopbackAddress()) {
                return OrbSettings.LOOPBACK;
            }
            try (java.net.Socket probe = new java.net.Socket()) {
                probe.connect(new java.net.InetSocketAddress(address, Integer.parseInt(m.group(2))), 2_000);
                return probe.getLocalAddress().getHostAddress();
            }
        } catch (java.io.IOException | NumberFormatException e) {
            LOG.debug("no route to {} ({}); listening on 127.0.0.1", host, e.toString());
            return OrbSettings.LOOPBACK;
        }
    }

    private static RunningNetwork locate(OrbRuntime orb, String target, String namingCorbaloc, String[] where) {
        String ref;
        if (target.startsWith("corbaloc:") || target.startsWith("IOR:") || target.startsWith("corbaname:")) {
            ref = target;
        } else if (target.matches(".+:[0-9]{1,5}")) {
            ref = "corbaloc::" + target + "/" + ControlPublication.OBJECT_KEY;
        } else {
            ref = RunFiles.read(target).orElse(null);
            if (ref == null) {
                if (namingCorbaloc == null) {
                    throw new NetworkUnreachableException("no network named '" + target + "' runs on this machine ("
                            + RunFiles.fileOf(target) + " does not exist or names a stopped process); give its address"
                            + " (HOST:PORT or corbaloc) or --naming");
                }
                where[0] = "naming service " + namingCorbaloc + " as '" + target + "'";
                return NetworkDirectory.connect(orb).find(target).orElseThrow(() -> new NetworkUnreachableException(
                        "no network named '" + target + "' is registered in the naming service " + namingCorbaloc));
            }
        }
        where[0] = ref.startsWith("IOR:") ? "'" + target + "'" : ref;
        try {
            return RunningNetworkHelper.unchecked_narrow(orb.orb().string_to_object(OrbSettings.reference(ref)));
        } catch (org.omg.CORBA.BAD_PARAM e) {
            throw new NetworkUnreachableException("'" + target + "' is not an address of a network (" + e + ")", e);
        }
    }

    /** Where this network was reached: a corbaloc, or the naming service and name. */
    public String address() {
        return address;
    }

    @Override
    public String name() {
        return name;
    }

    @Override
    public NetworkInfo snapshot() {
        String text = query(remote::snapshot);
        try {
            return NetworkRepository.fromText(text, "snapshot of " + name);
        } catch (NetworkFileException e) {
            throw new IllegalStateException("network " + name + " at " + address + " sent a snapshot that is not a"
                    + " valid network: " + e.getMessage(), e);
        }
    }

    /** Asked of the run each time (empty when it does not know its logger's viewer address). */
    @Override
    public Optional<String> loggerViewerAddress() {
        String text = query(remote::loggerViewerAddress);
        return text.isBlank() ? Optional.empty() : Optional.of(text);
    }

    @Override
    public Set<String> loadedModules() {
        return new LinkedHashSet<>(List.of(query(remote::loadedModules)));
    }

    @Override
    public Set<String> heldModules() {
        return new LinkedHashSet<>(List.of(query(remote::heldModules)));
    }

    @Override
    public ChangeOutcome apply(String description, NetworkInfo base, NetworkInfo edited) {
        String baseText = NetworkRepository.toText(base);
        String editedText = NetworkRepository.toText(edited);
        return change(description, () -> remote.applyChange(baseText, editedText, description));
    }

    /** The edit is made here on a snapshot; the network then applies the difference (refused if it no longer fits). */
    @Override
    public ChangeOutcome apply(String description, NetworkEdit edit) {
        NetworkInfo base;
        try {
            base = snapshot();
        } catch (NetworkUnreachableException e) {
            return ChangeOutcome.failed(description, e.getMessage());
        }
        NetworkInfo edited = base.copy();
        try {
            edit.applyTo(edited);
        } catch (EditRefusedException e) {
            return ChangeOutcome.failed(description, e.getMessage());
        }
        return apply(description, base, edited);
    }

    @Override
    public ChangeOutcome load(String module) {
        return change("load " + module, () -> remote.load(module));
    }

    @Override
    public ChangeOutcome unload(String module) {
        return change("unload " + module, () -> remote.unload(module));
    }

    @Override
    public ChangeOutcome hold(String module) {
        return change("hold " + module, () -> remote.hold(module));
    }

    @Override
    public ChangeOutcome resume(String module) {
        return change("resume " + module, () -> remote.resume(module));
    }

    @Override
    public ChangeOutcome setParameter(NodeRef node, String parameter, String value) {
        return change("set " + node + ":" + parameter + "=" + value,
                () -> remote.setParameter(IdlMapping.id(node), parameter, value));
    }

    @Override
    public ChangeOutcome send(NodeRef data, String text) {
        return change("send " + data + "=" + text, () -> remote.send(IdlMapping.id(data), text));
    }

    @Override
    public AutoCloseable subscribe(LiveNetworkListener listener) {
        ListenerServant servant = new ListenerServant(listener);
        if (unreachable != null) {
            servant.disconnected(unreachable);
            return () -> { };
        }
        servant.reference = RunningNetworkListenerHelper.narrow(orb.activate(servant));
        try {
            remote.subscribe(servant.reference);
        } catch (SystemException e) {
            orb.deactivate(servant);
            lost(e);
            servant.disconnected(unreachable);
            return () -> { };
        }
        listeners.add(servant);
        if (watching.compareAndSet(false, true)) {
            startWatching();
        }
        return () -> end(servant, true);
    }

    private synchronized void startWatching() {
        if (watchdog.isShutdown()) {
            return;
        }
        try {
            watchdog.scheduleWithFixedDelay(this::watch, WATCH_MILLIS, WATCH_MILLIS, TimeUnit.MILLISECONDS);
        } catch (java.util.concurrent.RejectedExecutionException closed) {
            LOG.debug("not watching {}: closed", name);
        }
    }

    private void watch() {
        if (unreachable != null || listeners.isEmpty()) {
            return;
        }
        try {
            long now = remote.ping();
            if (now != incarnation) {
                lostWith("network " + name + " at " + address + " was restarted; attach again");
            }
        } catch (SystemException e) {
            lost(e);
        }
    }

    private void lost(SystemException e) {
        lostWith("network " + name + " at " + address + " cannot be reached (" + reason(e) + ")");
    }

    private void lostWith(String reason) {
        if (unreachable != null) {
            return;
        }
        unreachable = reason;
        LOG.info("{}", reason);
        for (ListenerServant s : listeners) {
            s.disconnected(reason);
            end(s, false);
        }
    }

    private void end(ListenerServant servant, boolean unsubscribe) {
        if (!listeners.remove(servant)) {
            return;
        }
        if (unsubscribe && unreachable == null) {
            try {
                remote.unsubscribe(servant.reference);
            } catch (SystemException e) {
                LOG.debug("unsubscribe from {} failed: {}", name, e.toString());
            }
        }
        orb.deactivate(servant);
    }

    /** Lets go of the network (its listeners hear nothing more); the network keeps running. */
    @Override
    public void close() {
        watchdog.shutdownNow();
        for (ListenerServant s : List.copyOf(listeners)) {
            end(s, true);
        }
        orb.close();
    }

    private <T> T query(Supplier<T> call) {
        String dead = unreachable;
        if (dead != null) {
            throw new NetworkUnreachableException(dead);
        }
        try {
            return call.get();
        } catch (SystemException e) {
            lost(e);
            throw new NetworkUnreachableException(unreachable, e);
        }
    }

    private ChangeOutcome change(String description, Supplier<ChangeResult> call) {
        String dead = unreachable;
        if (dead != null) {
            return ChangeOutcome.failed(description, dead);
        }
        try {
            ChangeResult r = call.get();
            return r.executed ? ChangeOutcome.executed(r.description)
                    : ChangeOutcome.failed(r.description, r.reason);
        } catch (SystemException e) {
            lost(e);
            return ChangeOutcome.failed(description, unreachable);
        }
    }

    private static String reason(SystemException e) {
        String simple = e.getClass().getSimpleName();
        String message = e.getMessage();
        if (e instanceof org.omg.CORBA.TIMEOUT) {
            return "no answer within " + CALL_TIMEOUT_MILLIS + " ms";
        }
        if (e instanceof org.omg.CORBA.TRANSIENT || e instanceof org.omg.CORBA.COMM_FAILURE) {
            return "connection failed: " + simple + (message == null || message.isBlank() ? "" : ": " + message);
        }
        if (e instanceof org.omg.CORBA.OBJECT_NOT_EXIST) {
            return "the run no longer publishes its control object";
        }
        return simple + (message == null ? "" : ": " + message);
    }

    /** One subscriber's callbacks, served by this process's ORB; {@code disconnected} reaches its listener once. */
    private final class ListenerServant extends RunningNetworkListenerPOA {
        private final LiveNetworkListener listener;
        private final AtomicBoolean ended = new AtomicBoolean();
        org.fdnet.corba.idl.RunningNetworkListener reference;

        ListenerServant(LiveNetworkListener listener) {
            this.listener = listener;
        }

        @Override
        public void changeSettled(ChangeResult outcome) {
            if (!ended.get()) {
                ChangeOutcome o = outcome.executed ? ChangeOutcome.executed(outcome.description)
                        : ChangeOutcome.failed(outcome.description, outcome.reason);
                guarded(() -> listener.changeSettled(o), "changeSettled");
            }
        }

        /** {@code valuesSampled} is read by {@link CheckedValueReader}: hostile bytes are refused before any allocation. */
        @Override
        public org.omg.CORBA.portable.OutputStream _invoke(String method, org.omg.CORBA.portable.InputStream input,
                org.omg.CORBA.portable.ResponseHandler handler) {
            if (!"valuesSampled".equals(method)) {
                return super._invoke(method, input, handler);
            }
            SampledValue[] latest = CheckedValueReader.sampled(input);
            org.omg.CORBA.portable.OutputStream out = handler.createReply();
            valuesSampled(latest);
            return out;
        }

        @Override
        public void valuesSampled(SampledValue[] latest) {
            if (ended.get()) {
                return;
            }
            Map<NodeRef, Value> values = new LinkedHashMap<>();
            for (SampledValue v : latest) {
                values.put(IdlMapping.ref(v.data), ValueCodec.decodeRuntime(v.latest));
            }
            guarded(() -> listener.valuesSampled(values), "valuesSampled");
        }

        /** From the network (it stopped) or from the watchdog (it cannot be reached): the listener hears it once. */
        @Override
        public void disconnected(String reason) {
            if (ended.compareAndSet(false, true)) {
                guarded(() -> listener.disconnected(reason), "disconnected");
            }
            if (unreachable == null) {
                try {
                    watchdog.execute(() -> lostWith("network " + name + " at " + address + ": " + reason));
                } catch (java.util.concurrent.RejectedExecutionException closed) {
                    LOG.debug("{} closed: {}", name, reason);
                }
            }
        }

        private void guarded(Runnable call, String what) {
            try {
                call.run();
            } catch (RuntimeException e) {
                LOG.warn("a live network listener failed in {}: {}", what, e.toString(), e);
            }
        }
    }
}

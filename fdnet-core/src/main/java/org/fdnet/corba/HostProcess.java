package org.fdnet.corba;

import java.util.Objects;
import org.fdnet.corba.idl.Host;
import org.fdnet.corba.idl.HostHelper;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One running FDNet host: an ORB, the {@link HostServant} over a {@link LocalNetwork}, and its name in the
 * naming service. {@code fdnet host} runs one per process; the benchmark and tests may run one in-process.
 * {@link #close()} unregisters the name (when it is still ours), stops the links, the ORB and the engine.
 */
public final class HostProcess implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(HostProcess.class);
    private static final long REGISTRATION_CHECK_MILLIS = 1_000;

    private final OrbRuntime orb;
    private final HostServant servant;
    private final Host reference;
    private final HostDirectory directory;
    private final String name;
    private final LocalNetwork network;
    private volatile boolean closed;

    private HostProcess(OrbRuntime orb, HostServant servant, Host reference, HostDirectory directory, String name,
                        LocalNetwork network) {
        this.network = network;
        this.orb = orb;
        this.servant = servant;
        this.reference = reference;
        this.directory = directory;
        this.name = name;
    }

    /** Starts the host and registers it under {@code name}; the naming service must be reachable. */
    public static HostProcess start(String name, OrbSettings settings, LocalNetwork network, ClassPolicy policy,
                                    LinkSettings links) {
        Objects.requireNonNull(name, "name");
        if (name.isBlank() || name.contains("/")) {
            throw new IllegalArgumentException("host name must be non-blank and without '/', was '" + name + "'");
        }
        OrbRuntime orb = OrbRuntime.start(settings);
        try {
            HostServant servant = new HostServant(name, network, policy, links, orb.orb());
            Host ref = HostHelper.narrow(orb.activate(servant));
            HostDirectory directory = HostDirectory.connect(orb);
            directory.register(name, ref);
            LOG.info("host {} registered in {}", name, directory.where());
            HostProcess host = new HostProcess(orb, servant, ref, directory, name, network);
            host.keepRegistered();
            return host;
        } catch (RuntimeException e) {
            orb.close();
            throw e;
        }
    }

    public String name() {
        return name;
    }

    /**
     * A restarted naming service has forgotten every binding: register again when the name is missing. A name bound
     * to another reference belongs to a newer incarnation of this host (this one was thought dead) and is left alone.
     */
    private void keepRegistered() {
        Thread watcher = new Thread(() -> {
            while (!closed) {
                try {
                    Thread.sleep(REGISTRATION_CHECK_MILLIS);
                    if (!closed && directory.find(name).isEmpty()) {
                        directory.register(name, reference);
                        LOG.warn("host {} registered again: the naming service had forgotten it (restarted?)", name);
                    }
                } catch (HostUnreachableException | org.omg.CORBA.SystemException e) {
                    LOG.debug("host {}: naming service not reachable now: {}", name, e.toString());
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "fdnet-host-registration");
        watcher.setDaemon(true);
        watcher.start();
    }

    public Host reference() {
        return reference;
    }

    public HostServant servant() {
        return servant;
    }

    public OrbRuntime orb() {
        return orb;
    }

    @Override
    public void close() {
        closed = true;
        try {
            // Only remove the binding if it is still ours: a restarted host may have rebound the name.
            directory.find(name).filter(h -> h._is_equivalent(reference)).ifPresent(h -> directory.unregister(name));
        } catch (HostUnreachableException e) {
            LOG.info("could not unregister {}: {}", name, e.getMessage());
        }
        servant.close();
        orb.close();
        if (network instanceof AutoCloseable engine) {
            try {
                engine.close();
            } catch (Exception e) {
                LOG.warn("host {}: its engine did not stop cleanly: {}", name, e.toString(), e);
            }
        }
    }

    public LocalNetwork network() {
        return network;
    }
}

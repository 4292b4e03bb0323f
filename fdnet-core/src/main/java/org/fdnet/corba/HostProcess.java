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

    private final OrbRuntime orb;
    private final HostServant servant;
    private final Host reference;
    private final HostDirectory directory;
    private final String name;
    private final LocalNetwork network;

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
            return new HostProcess(orb, servant, ref, directory, name, network);
        } catch (RuntimeException e) {
            orb.close();
            throw e;
        }
    }

    public String name() {
        return name;
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

package org.fdnet.corba.control;

import java.io.IOException;
import java.net.InetSocketAddress;
import java.net.ServerSocket;
import java.nio.charset.StandardCharsets;
import org.fdnet.control.LiveNetwork;
import org.fdnet.control.NetworkUnreachableException;
import org.fdnet.corba.OrbRuntime;
import org.fdnet.corba.OrbSettings;
import org.fdnet.corba.idl.RunningNetwork;
import org.fdnet.corba.idl.RunningNetworkHelper;
import org.omg.CORBA.Policy;
import org.omg.PortableServer.IdAssignmentPolicyValue;
import org.omg.PortableServer.LifespanPolicyValue;
import org.omg.PortableServer.POA;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A running network's control object, published: the {@link RunningNetworkImpl} over the run's
 * {@link LiveNetwork}, reachable
 * <ul>
 *   <li>on a port of its own ({@link #atPort}, a run in one process): {@code corbaloc::ADDRESS:PORT/FDNetControl},
 *       ADDRESS 127.0.0.1 unless the user names another; or</li>
 *   <li>through the naming service ({@link #inNaming}, a distributed run): the network's name, kind
 *       {@value NetworkDirectory#KIND}, on the run's own ORB;</li>
 * </ul>
 * and in both cases through {@code ~/.fdnet/run/NAME.ref} ({@link RunFiles}) for {@code --attach NAME} on this
 * machine. {@link #close(String)} tells every subscribed tool why the network stopped, then withdraws it all.
 */
public final class ControlPublication implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(ControlPublication.class);
    /** The short object key of {@code corbaloc::ADDRESS:PORT/FDNetControl}. */
    public static final String OBJECT_KEY = "FDNetControl";
    private static final String IMPL_NAME = "fdnet";
    private static final String POA_NAME = "fdnet-control";
    private static final String OBJECT_ID = "network";

    private final String name;
    private final RunningNetworkImpl servant;
    private final RunningNetwork reference;
    private final String address;
    private final String where;
    private final OrbRuntime ownOrb;
    private final NetworkDirectory directory;
    private boolean closed;

    private ControlPublication(String name, RunningNetworkImpl servant, RunningNetwork reference, String address,
                               String where, OrbRuntime ownOrb, NetworkDirectory directory) {
        this.name = name;
        this.servant = servant;
        this.reference = reference;
        this.address = address;
        this.where = where;
        this.ownOrb = ownOrb;
        this.directory = directory;
    }

    /**
     * Publishes on an ORB of its own that listens on {@code bindAddress}:{@code port} (0: a free port).
     *
     * @throws IllegalStateException naming the address when it cannot listen there
     */
    public static ControlPublication atPort(LiveNetwork network, String bindAddress, int port) {
        int chosen = port != 0 ? port : freePort(bindAddress);
        OrbSettings settings = OrbSettings.defaults().withBindAddress(bindAddress).withPort(chosen);
        OrbRuntime orb;
        try {
            orb = OrbRuntime.start(settings,
                    settings.toOrbProperties(IMPL_NAME, OBJECT_KEY, IMPL_NAME + "/" + POA_NAME + "/" + OBJECT_ID));
        } catch (RuntimeException e) {
            throw new IllegalStateException("cannot publish the control object on " + bindAddress + ":" + chosen
                    + ": " + e.getMessage(), e);
        }
        try {
            POA root = orb.rootPoa();
            POA poa = root.create_POA(POA_NAME, root.the_POAManager(), new Policy[] {
                    root.create_lifespan_policy(LifespanPolicyValue.PERSISTENT),
                    root.create_id_assignment_policy(IdAssignmentPolicyValue.USER_ID)});
            RunningNetworkImpl servant = new RunningNetworkImpl(network, orb.orb());
            byte[] id = OBJECT_ID.getBytes(StandardCharsets.US_ASCII);
            poa.activate_object_with_id(id, servant);
            RunningNetwork ref = RunningNetworkHelper.narrow(poa.id_to_reference(id));
            String address = OrbSettings.reference("corbaloc::" + bindAddress + ":" + chosen + "/" + OBJECT_KEY);
            ControlPublication p = new ControlPublication(network.name(), servant, ref, address, address, orb, null);
            p.writeRunFile();
            return p;
        } catch (org.omg.CORBA.UserException | RuntimeException e) {
            orb.close();
            throw new IllegalStateException("cannot publish the control object on " + bindAddress + ":" + chosen
                    + ": " + e, e);
        }
    }

    /** Publishes on the run's own ORB and registers it in the naming service that ORB was given. */
    public static ControlPublication inNaming(LiveNetwork network, OrbRuntime orb) {
        RunningNetworkImpl servant = new RunningNetworkImpl(network, orb.orb());
        RunningNetwork ref = RunningNetworkHelper.narrow(orb.activate(servant));
        NetworkDirectory directory;
        try {
            directory = NetworkDirectory.connect(orb);
            directory.register(network.name(), ref);
        } catch (NetworkUnreachableException e) {
            orb.deactivate(servant);
            throw e;
        }
        ControlPublication p = new ControlPublication(network.name(), servant, ref, orb.orb().object_to_string(ref),
                "naming service " + directory.where() + " as '" + network.name() + "'", null, directory);
        p.writeRunFile();
        return p;
    }

    private void writeRunFile() {
        try {
            RunFiles.write(name, address);
        } catch (IOException e) {
            LOG.warn("cannot write {} ({}); attach with the address instead", RunFiles.fileOf(name), e.toString());
        }
    }

    /** The one line a run prints about its control object. */
    public String announcement() {
        return "control object of " + name + ": " + where + " (fdnet control " + quoted(name)
                + " status; fdnet hi --attach " + quoted(name) + ")";
    }

    private static String quoted(String name) {
        return name.matches("[A-Za-z0-9._/-]+") ? name : "'" + name + "'";
    }

    /** {@code corbaloc::…} or {@code IOR:…}: what a tool passes to attach from anywhere that reaches it. */
    public String address() {
        return address;
    }

    public RunningNetwork reference() {
        return reference;
    }

    /** Tells subscribed tools that the network stopped ({@code reason}), then withdraws the object. */
    public synchronized void close(String reason) {
        if (closed) {
            return;
        }
        closed = true;
        servant.close(reason);
        RunFiles.remove(name, address);
        if (directory != null) {
            try {
                directory.unregister(name, reference);
            } catch (NetworkUnreachableException e) {
                LOG.info("{}", e.getMessage());
            }
        }
        if (ownOrb != null) {
            ownOrb.close();
        } else {
            try {
                servant._poa().deactivate_object(servant._object_id());
            } catch (org.omg.CORBA.UserException | RuntimeException e) {
                LOG.debug("control object was not active: {}", e.toString());
            }
        }
    }

    @Override
    public void close() {
        close("the network " + name + " stopped");
    }

    private static int freePort(String bindAddress) {
        try (ServerSocket probe = new ServerSocket()) {
            probe.bind(new InetSocketAddress(bindAddress, 0));
            return probe.getLocalPort();
        } catch (IOException e) {
            throw new IllegalStateException("cannot find a free port on " + bindAddress + ": " + e.getMessage(), e);
        }
    }
}

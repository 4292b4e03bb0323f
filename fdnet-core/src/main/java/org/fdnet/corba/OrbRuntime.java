package org.fdnet.corba;

import java.util.Objects;
import org.omg.CORBA.ORB;
import org.omg.CORBA.ORBPackage.InvalidName;
import org.omg.PortableServer.POA;
import org.omg.PortableServer.POAHelper;
import org.omg.PortableServer.POAManagerPackage.AdapterInactive;
import org.omg.PortableServer.Servant;
import org.omg.PortableServer.POAPackage.ServantNotActive;
import org.omg.PortableServer.POAPackage.WrongPolicy;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * One started JacORB ORB with its root POA active: the only place FDNet calls {@code ORB.init}.
 *
 * <p>Before the first ORB starts it applies the JDK 17 fix ({@code javax.rmi.CORBA.StubClass}, see
 * {@link FdnetStubDelegate}) and quiets JacORB's INFO chatter unless the user chose a level. Requests are
 * served by JacORB's own threads; nothing needs {@code orb.run()}. {@link #close()} shuts the ORB down
 * and so closes every connection it holds.
 */
public final class OrbRuntime implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(OrbRuntime.class);
    private static final String STUB_CLASS_KEY = "javax.rmi.CORBA.StubClass";
    private static final String JACORB_LOG_LEVEL_KEY = "org.slf4j.simpleLogger.log.org.jacorb";

    private final ORB orb;
    private final POA rootPoa;
    private final OrbSettings settings;

    private OrbRuntime(ORB orb, POA rootPoa, OrbSettings settings) {
        this.orb = orb;
        this.rootPoa = rootPoa;
        this.settings = settings;
    }

    /** Sets the JVM-wide properties JacORB needs on JDK 17; idempotent, and safe before any CORBA class loads. */
    public static void prepareJvm() {
        if (System.getProperty(STUB_CLASS_KEY) == null) {
            System.setProperty(STUB_CLASS_KEY, FdnetStubDelegate.class.getName());
        }
        if (System.getProperty(JACORB_LOG_LEVEL_KEY) == null) {
            System.setProperty(JACORB_LOG_LEVEL_KEY, "warn");
        }
    }

    public static OrbRuntime start(OrbSettings settings) {
        Objects.requireNonNull(settings, "settings");
        return start(settings, settings.toOrbProperties());
    }

    /** Starts an ORB with {@code properties} made by {@code settings} (e.g. {@link OrbSettings#toOrbProperties(String, String, String)}). */
    public static OrbRuntime start(OrbSettings settings, java.util.Properties properties) {
        Objects.requireNonNull(settings, "settings");
        prepareJvm();
        ORB orb = ORB.init(new String[0], properties);
        try {
            POA root = POAHelper.narrow(orb.resolve_initial_references("RootPOA"));
            root.the_POAManager().activate();
            LOG.debug("ORB started on {} (port {})", settings.bindAddress(), settings.port());
            return new OrbRuntime(orb, root, settings);
        } catch (InvalidName | AdapterInactive e) {
            orb.shutdown(false);
            throw new IllegalStateException("JacORB started without a usable RootPOA", e);
        }
    }

    public ORB orb() {
        return orb;
    }

    public POA rootPoa() {
        return rootPoa;
    }

    public OrbSettings settings() {
        return settings;
    }

    /** Activates a servant on the root POA and returns its reference. */
    public org.omg.CORBA.Object activate(Servant servant) {
        try {
            return rootPoa.servant_to_reference(servant);
        } catch (ServantNotActive | WrongPolicy e) {
            throw new IllegalStateException("cannot activate " + servant.getClass().getSimpleName(), e);
        }
    }

    /** Deactivates a servant activated by {@link #activate}; later calls to it fail with OBJECT_NOT_EXIST. */
    public void deactivate(Servant servant) {
        try {
            rootPoa.deactivate_object(rootPoa.servant_to_id(servant));
        } catch (org.omg.CORBA.UserException e) {
            LOG.debug("servant {} was not active", servant.getClass().getSimpleName(), e);
        }
    }

    @Override
    public void close() {
        try {
            orb.shutdown(true);
        } catch (RuntimeException e) {
            LOG.warn("ORB shutdown failed: {}", e.toString(), e);
        } finally {
            orb.destroy();
        }
    }
}

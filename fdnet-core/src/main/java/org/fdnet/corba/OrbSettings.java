package org.fdnet.corba;

import java.nio.file.Path;
import java.util.Objects;
import java.util.Properties;
import org.fdnet.tls.TransportSecurity;

/**
 * Every setting of an FDNet ORB in one typed place: the JacORB property keys live here and nowhere else.
 * Immutable; the {@code with…} methods validate and return a copy.
 *
 * <p>Defaults are chosen for a robot network on a LAN: bind to 127.0.0.1 (nothing is exposed until the
 * user says {@code --bind}), fail a call to a dead host in well under a second (JacORB's default retries
 * for 2.5 s), and keep JacORB's request queue far above what the bounded link windows can fill.
 *
 * @param bindAddress     the address the ORB listens on and writes into its object references
 * @param port            the listening port; 0 picks a free one
 * @param namingReference the {@code corbaloc} of the naming service, or {@code null} when not needed
 * @param callTimeoutMillis how long a two-way call may wait for its reply before it fails
 * @param poaQueueMax     JacORB's per-POA request queue; calls beyond it are refused, never queued
 * @param poaThreadsMax   threads serving requests
 *
 * <p>When this process speaks TLS ({@link TransportSecurity}), the ORB listens and connects with SSLIOP only,
 * mutual authentication required both ways: no plain IIOP port is opened; every request it serves is checked against
 * the network's permissions for the certificate of the connection that carries it ({@link CallerInterceptor}).
 */
public record OrbSettings(String bindAddress, int port, String namingReference, int callTimeoutMillis,
                          int poaQueueMax, int poaThreadsMax) {

    public static final String LOOPBACK = "127.0.0.1";

    // JacORB and OMG property keys.
    private static final String ORB_CLASS = "org.omg.CORBA.ORBClass";
    private static final String ORB_SINGLETON_CLASS = "org.omg.CORBA.ORBSingletonClass";
    private static final String LISTEN_ADDRESS = "OAIAddr";
    private static final String LISTEN_PORT = "OAPort";
    private static final String NAMING_INIT_REF = "ORBInitRef.NameService";
    private static final String REPLY_TIMEOUT = "jacorb.connection.client.pending_reply_timeout";
    private static final String CONNECT_TIMEOUT = "jacorb.connection.client.connect_timeout";
    private static final String RETRIES = "jacorb.retries";
    private static final String RETRY_INTERVAL = "jacorb.retry_interval";
    private static final String POA_QUEUE_MAX = "jacorb.poa.queue_max";
    private static final String POA_QUEUE_MIN = "jacorb.poa.queue_min";
    private static final String POA_THREADS_MAX = "jacorb.poa.thread_pool_max";
    private static final String POA_THREADS_MIN = "jacorb.poa.thread_pool_min";
    private static final String NAMING_PRINT_IOR = "jacorb.naming.print_ior";
    private static final String NAMING_KEY = "jacorb.orb.objectKeyMap.NameService";
    private static final String NAMING_DB_DIR = "jacorb.naming.db_dir";
    private static final String IMPL_NAME = "jacorb.implname";
    private static final String OBJECT_KEY_MAP = "jacorb.orb.objectKeyMap.";
    private static final String LISTEN_TLS_PORT = "OASSLPort";
    private static final String SUPPORT_SSL = "jacorb.security.support_ssl";
    private static final String SSL_SOCKET_FACTORY = "jacorb.ssl.socket_factory";
    private static final String SSL_SERVER_SOCKET_FACTORY = "jacorb.ssl.server_socket_factory";
    private static final String ORB_INITIALIZER = "org.omg.PortableInterceptor.ORBInitializerClass.";
    private static final String[] SSL_OPTIONS = {"jacorb.security.ssl.client.supported_options",
            "jacorb.security.ssl.client.required_options", "jacorb.security.ssl.server.supported_options",
            "jacorb.security.ssl.server.required_options", "jacorb.security.ssl.corbaloc_ssliop.supported_options",
            "jacorb.security.ssl.corbaloc_ssliop.required_options"};
    /** EstablishTrustInTarget | EstablishTrustInClient (hex, as JacORB reads it): both ends prove who they are. */
    private static final String MUTUAL_TRUST = "60";
    private static final java.util.regex.Pattern PLAIN_CORBALOC =
            java.util.regex.Pattern.compile("corbaloc:(?:iiop)?:(?:[0-9.]+@)?(.+)");

    public OrbSettings {
        Objects.requireNonNull(bindAddress, "bindAddress");
        if (bindAddress.isBlank()) {
            throw new IllegalArgumentException("bindAddress must not be blank");
        }
        if (port < 0 || port > 65535) {
            throw new IllegalArgumentException("port must be 0..65535, was " + port);
        }
        if (callTimeoutMillis < 1) {
            throw new IllegalArgumentException("callTimeoutMillis must be at least 1, was " + callTimeoutMillis);
        }
        if (poaQueueMax < 1) {
            throw new IllegalArgumentException("poaQueueMax must be at least 1, was " + poaQueueMax);
        }
        if (poaThreadsMax < 1) {
            throw new IllegalArgumentException("poaThreadsMax must be at least 1, was " + poaThreadsMax);
        }
    }

    /** Loopback, any free port, no naming service. */
    public static OrbSettings defaults() {
        return new OrbSettings(LOOPBACK, 0, null, 5_000, 10_000, 32);
    }

    /** {@code corbaloc::ADDRESS:PORT/NameService}, or its SSLIOP form when this process speaks TLS. */
    public static String namingCorbaloc(String address, int port) {
        return reference("corbaloc::" + address + ":" + port + "/NameService");
    }

    /**
     * {@code corbaloc} as this process must use it: when it speaks TLS ({@link TransportSecurity}), an IIOP corbaloc
     * becomes {@code corbaloc:ssliop:1.2@ADDRESS:PORT/KEY} (JacORB takes TLS only with the version given); anything
     * else is returned as it is.
     */
    public static String reference(String corbaloc) {
        if (corbaloc == null || !TransportSecurity.isOn()) {
            return corbaloc;
        }
        java.util.regex.Matcher m = PLAIN_CORBALOC.matcher(corbaloc);
        return m.matches() ? "corbaloc:ssliop:1.2@" + m.group(1) : corbaloc;
    }

    public OrbSettings withBindAddress(String address) {
        return new OrbSettings(address, port, namingReference, callTimeoutMillis, poaQueueMax, poaThreadsMax);
    }

    public OrbSettings withPort(int newPort) {
        return new OrbSettings(bindAddress, newPort, namingReference, callTimeoutMillis, poaQueueMax, poaThreadsMax);
    }

    public OrbSettings withNaming(String corbaloc) {
        return new OrbSettings(bindAddress, port, corbaloc, callTimeoutMillis, poaQueueMax, poaThreadsMax);
    }

    public OrbSettings withCallTimeoutMillis(int millis) {
        return new OrbSettings(bindAddress, port, namingReference, millis, poaQueueMax, poaThreadsMax);
    }

    /** The properties handed to {@code ORB.init}. */
    public Properties toOrbProperties() {
        Properties p = new Properties();
        p.setProperty(ORB_CLASS, "org.jacorb.orb.ORB");
        p.setProperty(ORB_SINGLETON_CLASS, "org.jacorb.orb.ORBSingleton");
        p.setProperty(LISTEN_ADDRESS, bindAddress);
        boolean tls = TransportSecurity.isOn();
        if (port != 0) {
            p.setProperty(tls ? LISTEN_TLS_PORT : LISTEN_PORT, Integer.toString(port));
        }
        if (namingReference != null) {
            p.setProperty(NAMING_INIT_REF, reference(namingReference));
        }
        if (tls) {
            p.setProperty(SUPPORT_SSL, "on");
            p.setProperty(SSL_SOCKET_FACTORY, IiopTlsSocketFactory.class.getName());
            p.setProperty(SSL_SERVER_SOCKET_FACTORY, IiopTlsServerSocketFactory.class.getName());
            p.setProperty(ORB_INITIALIZER + CallerInterceptor.Installer.class.getName(), "");
            for (String option : SSL_OPTIONS) {
                p.setProperty(option, MUTUAL_TRUST);
            }
        }
        p.setProperty(REPLY_TIMEOUT, Integer.toString(callTimeoutMillis));
        p.setProperty(CONNECT_TIMEOUT, Integer.toString(Math.min(callTimeoutMillis, 2_000)));
        // A dead host must be noticed quickly; links and the coordinator retry on their own terms.
        p.setProperty(RETRIES, "0");
        p.setProperty(RETRY_INTERVAL, "100");
        p.setProperty(POA_QUEUE_MAX, Integer.toString(poaQueueMax));
        p.setProperty(POA_QUEUE_MIN, Integer.toString(Math.max(1, poaQueueMax / 2)));
        p.setProperty(POA_THREADS_MAX, Integer.toString(poaThreadsMax));
        p.setProperty(POA_THREADS_MIN, Integer.toString(Math.min(4, poaThreadsMax)));
        return p;
    }

    /**
     * The properties of an ORB that serves one object at a well-known address, {@code corbaloc::ADDRESS:PORT/shortKey}
     * (a network's control object): persistent object keys start with {@code implName}, and {@code shortKey}
     * maps to the object's full key, {@code implName/POA/id}.
     */
    public Properties toOrbProperties(String implName, String shortKey, String objectKey) {
        Properties p = toOrbProperties();
        p.setProperty(IMPL_NAME, implName);
        p.setProperty(OBJECT_KEY_MAP + shortKey, objectKey);
        return p;
    }

    /**
     * The extra properties JacORB's NameServer needs to answer {@code corbaloc::…/NameService}; it keeps
     * its bindings in {@code stateDirectory} (by default it would write them into the working directory).
     */
    public Properties toNamingServerProperties(Path stateDirectory) {
        Properties p = toOrbProperties();
        p.setProperty(NAMING_DB_DIR, stateDirectory.toString());
        p.setProperty(NAMING_PRINT_IOR, "false");
        p.setProperty(NAMING_KEY, "StandardNS/NameServer-POA/_root");
        return p;
    }
}

package org.fdnet.corba;

import java.util.List;
import java.util.Set;
import java.util.TreeSet;
import org.fdnet.corba.idl.ConnectionSpec;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.ModuleInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.tls.Permissions;
import org.fdnet.tls.Right;
import org.fdnet.tls.TransportSecurity;
import org.omg.CORBA.CompletionStatus;
import org.omg.CORBA.NO_PERMISSION;

/**
 * Who made the remote call this thread serves, and whether the network's permissions let it: servants ask here before
 * they change or reveal anything. {@link CallerInterceptor} names the caller from the TLS session of the connection
 * that carries the request; a call that came through no TLS connection is this process's own. Without TLS every
 * check passes ({@link TransportSecurity#permissions}).
 *
 * <p>A refusal names the certificate, the node or module and the right it lacks; servants throw it as
 * {@code NO_PERMISSION} (its text reaches the caller in the reply's exception detail) or return it where their
 * operation answers with a reason, and apply nothing of the call.
 */
public final class Caller {
    private static final ThreadLocal<String> NAME = new ThreadLocal<>();
    /** The module pattern only a grant of every module ({@code *}) matches. */
    private static final String EVERY_MODULE = "*";

    private Caller() {
    }

    static void enter(String certificateName) {
        NAME.set(certificateName);
    }

    static void leave() {
        NAME.remove();
    }

    /**
     * The certificate name of the member whose request this thread serves.
     *
     * @return the peer's name; this process's own name for a call that came through no TLS connection; empty without
     *         TLS
     */
    public static String name() {
        String peer = NAME.get();
        if (peer != null) {
            return peer;
        }
        return TransportSecurity.current().map(t -> t.name()).orElse("");
    }

    /**
     * Why the caller may not use {@code right} on a node.
     *
     * @param right {@link Right#READ} or {@link Right#WRITE}
     * @param node  the node
     * @return null when it may
     */
    public static String refusal(Right right, NodeRef node) {
        Permissions p = TransportSecurity.permissions();
        return p.refusal(name(), right, node.module(), node.node());
    }

    /**
     * Why the caller may not use {@code right} on a module.
     *
     * @param right  {@link Right#LOAD}, {@link Right#UNLOAD} or {@link Right#RESHAPE}
     * @param module the module
     * @return null when it may
     */
    public static String refusal(Right right, String module) {
        return TransportSecurity.permissions().refusal(name(), right, module);
    }

    /**
     * Why the caller may not make the change from {@code before} to {@code after}: it needs {@link Right#RESHAPE} on
     * every module the change adds, removes or alters, and on the modules of both ends of every connection it makes or
     * removes (a module's connection may read or write another module's node), as a host asks of a share change.
     *
     * @param before the network as it is
     * @param after  the network as the caller wants it
     * @return null when it may
     */
    public static String refusalToEdit(NetworkInfo before, NetworkInfo after) {
        Set<String> names = new TreeSet<>();
        before.modules().forEach(m -> names.add(m.name()));
        after.modules().forEach(m -> names.add(m.name()));
        Set<String> touched = new TreeSet<>();
        for (String module : names) {
            ModuleInfo was = before.module(module);
            ModuleInfo will = after.module(module);
            if (was == null || !was.equals(will)) {
                touched.add(module);
                addEndsOfChangedConnections(was, will, touched);
            }
        }
        for (String module : touched) {
            String refusal = refusal(Right.RESHAPE, module);
            if (refusal != null) {
                return refusal;
            }
        }
        return null;
    }

    private static void addEndsOfChangedConnections(ModuleInfo was, ModuleInfo will, Set<String> modules) {
        List<ConnectionInfo> before = was == null ? List.of() : was.connections();
        List<ConnectionInfo> after = will == null ? List.of() : will.connections();
        addEndsOfConnectionsNotIn(before, after, modules);
        addEndsOfConnectionsNotIn(after, before, modules);
    }

    private static void addEndsOfConnectionsNotIn(List<ConnectionInfo> these, List<ConnectionInfo> others,
                                                  Set<String> modules) {
        for (ConnectionInfo c : these) {
            if (others.stream().noneMatch(c::sameDeclaration)) {
                modules.add(c.data().module());
                modules.add(c.relation().module());
            }
        }
    }

    /**
     * Fails the call unless the caller may use {@code right} on {@code node}.
     *
     * @param right {@link Right#READ} or {@link Right#WRITE}
     * @param node  the node
     * @throws NO_PERMISSION with the refusal
     */
    public static void require(Right right, NodeRef node) {
        fail(refusal(right, node));
    }

    /**
     * Fails the call unless the caller may use {@code right} on {@code module}.
     *
     * @param right  a module right
     * @param module the module
     * @throws NO_PERMISSION with the refusal
     */
    public static void require(Right right, String module) {
        fail(refusal(right, module));
    }

    /**
     * Fails the call unless the caller may deploy a network's run on this host (record, size, trace it, tell it the
     * coordinator): that is loading its module {@code main}.
     *
     * @throws NO_PERMISSION with the refusal
     */
    public static void requireDeploy() {
        require(Right.LOAD, ModuleInfo.MAIN);
    }

    /**
     * Fails the call unless the caller may reshape the modules of both ends of {@code connection}.
     *
     * @param connection a connection to make or remove
     * @throws NO_PERMISSION with the refusal
     */
    public static void requireReshape(ConnectionSpec connection) {
        require(Right.RESHAPE, connection.data.moduleName);
        require(Right.RESHAPE, connection.relation.moduleName);
    }

    /**
     * Fails the call unless the caller may use {@code right} on every module: a servant message can reach and
     * reshape the whole network.
     *
     * @param right a module right
     * @throws NO_PERMISSION with the refusal
     */
    public static void requireEveryModule(Right right) {
        fail(refusal(right, EVERY_MODULE));
    }

    /**
     * Throws a refusal as the call's failure.
     *
     * @param refusal null (nothing happens) or the reason
     * @throws NO_PERMISSION with the reason, the call not completed
     */
    public static void fail(String refusal) {
        if (refusal != null) {
            throw new NO_PERMISSION(refusal, 0, CompletionStatus.COMPLETED_NO);
        }
    }
}

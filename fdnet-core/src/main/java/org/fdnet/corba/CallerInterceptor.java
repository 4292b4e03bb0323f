package org.fdnet.corba;

import org.fdnet.tls.PeerCertificate;
import org.jacorb.orb.giop.GIOPConnection;
import org.jacorb.orb.iiop.ServerIIOPConnection;
import org.jacorb.orb.portableInterceptor.ServerRequestInfoImpl;
import org.omg.CORBA.LocalObject;
import org.omg.PortableInterceptor.ORBInitInfo;
import org.omg.PortableInterceptor.ORBInitInfoPackage.DuplicateName;
import org.omg.PortableInterceptor.ORBInitializer;
import org.omg.PortableInterceptor.ServerRequestInfo;
import org.omg.PortableInterceptor.ServerRequestInterceptor;

/**
 * Names the caller of every request this ORB serves ({@link Caller}) from the TLS session of the connection that
 * carries it: JacORB calls {@code receive_request} on the thread that then runs the servant, after it read the request.
 * The name is kept in the session ({@link PeerCertificate}), so a connection's requests after the first cost a map
 * look-up. Installed by {@link OrbSettings} when the process speaks TLS.
 */
public final class CallerInterceptor extends LocalObject implements ServerRequestInterceptor {
    private static final long serialVersionUID = 1L;

    @Override
    public void receive_request_service_contexts(ServerRequestInfo ri) {
        // the caller is named on the servant's thread, in receive_request
    }

    @Override
    public void receive_request(ServerRequestInfo ri) {
        Caller.enter(peer(ri));
    }

    @Override
    public void send_reply(ServerRequestInfo ri) {
        Caller.leave();
    }

    @Override
    public void send_exception(ServerRequestInfo ri) {
        Caller.leave();
    }

    @Override
    public void send_other(ServerRequestInfo ri) {
        Caller.leave();
    }

    @Override
    public String name() {
        return "fdnet-caller";
    }

    @Override
    public void destroy() {
        // holds nothing
    }

    private static String peer(ServerRequestInfo ri) {
        if (ri instanceof ServerRequestInfoImpl impl) {
            GIOPConnection connection = impl.getConnection();
            if (connection != null && connection.getTransport() instanceof ServerIIOPConnection transport) {
                return PeerCertificate.name(transport.getSocket());
            }
        }
        return null;
    }

    /** Registers the interceptor; JacORB instantiates it from the ORB's properties. */
    public static final class Installer extends LocalObject implements ORBInitializer {
        private static final long serialVersionUID = 1L;

        @Override
        public void pre_init(ORBInitInfo info) {
            try {
                info.add_server_request_interceptor(new CallerInterceptor());
            } catch (DuplicateName e) {
                throw new IllegalStateException("the caller interceptor is installed twice", e);
            }
        }

        @Override
        public void post_init(ORBInitInfo info) {
            // nothing after the ORB is made
        }
    }
}

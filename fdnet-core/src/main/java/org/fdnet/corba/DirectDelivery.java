package org.fdnet.corba;

import java.nio.ByteBuffer;
import java.util.Map;
import java.util.HashMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import org.fdnet.corba.idl.UnknownLink;
import org.fdnet.corba.idl.UnknownLinkHelper;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.corba.idl.ValueBatchHelper;
import org.fdnet.corba.idl.ValueSink;
import org.omg.CORBA.INTERNAL;
import org.omg.CORBA.ORB;
import org.omg.CORBA.SystemException;
import org.omg.CORBA.TypeCode;
import org.omg.CORBA.UserException;
import org.omg.CORBA.portable.ApplicationException;
import org.omg.CORBA.portable.InputStream;
import org.omg.CORBA.portable.InvokeHandler;
import org.omg.CORBA.portable.ObjectImpl;
import org.omg.CORBA.portable.OutputStream;
import org.omg.CORBA.portable.RemarshalException;
import org.omg.CORBA.portable.ResponseHandler;
import org.omg.Messaging.ExceptionHolder;
import org.omg.Messaging.ReplyHandler;
import org.omg.CORBA.Policy;
import org.omg.PortableServer.Current;
import org.omg.PortableServer.CurrentHelper;
import org.omg.PortableServer.CurrentPackage.NoContext;
import org.omg.PortableServer.IdAssignmentPolicyValue;
import org.omg.PortableServer.IdUniquenessPolicyValue;
import org.omg.PortableServer.POA;
import org.omg.PortableServer.POAHelper;
import org.omg.PortableServer.RequestProcessingPolicyValue;
import org.omg.PortableServer.Servant;
import org.omg.PortableServer.ServantRetentionPolicyValue;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Puts a {@code deliver} call on the wire without waiting for its reply: CORBA's asynchronous method invocation
 * through JacORB's delegate. The call stays a two-way call — its reply acknowledges the values exactly as a
 * blocking call's would — but the reply (or the exception in its place) comes back on the ORB's connection reader
 * thread, to {@link Replies}, instead of to a thread parked on it.
 *
 * <pre>
 *   send(sink, batch) ── request ──▶ peer's deliver ── reply ──▶ reader thread ─▶ ReplyServant ─▶ Replies
 * </pre>
 *
 * What it is for: the writer of a value on an idle {@link OutboundLink} sends it itself, so a lone value does not
 * pay for waking a sender thread (on each hop of a round trip through hosts). One instance serves one link and
 * one call at a time. The reply handlers of all links of an ORB are one servant, the default servant of a POA of
 * their own; each instance has its own object id there, so a reply finds the instance its call was made by — and a
 * reply that comes after its instance was {@link #close() closed} (a call given up at its timeout, answered when a
 * partition heals) finds no one and is dropped. Nothing is ever deactivated: JacORB closes the whole connection
 * when a reply's handler is gone.
 */
final class DirectDelivery implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(DirectDelivery.class);
    private static final String REPLY_HANDLER_ID = "IDL:omg.org/Messaging/ReplyHandler:1.0";
    private static final String REPLY_TIMEOUT = "jacorb.connection.client.pending_reply_timeout";
    private static final int MAX_REMARSHALS = 3;

    /** Where a call's outcome goes; called on the ORB's reader thread. */
    interface Replies {
        void replied(long expected);

        void failed(String reason);
    }

    /** Per ORB, its reply servant; an ORB's entry goes when {@link OrbRuntime} closes it ({@link #orbClosed}). */
    private static final Map<ORB, ReplyServant> SERVANTS = new HashMap<>();
    private static final AtomicLong INSTANCES = new AtomicLong();

    private final ReplyServant servant;
    private final long instance;
    private final ReplyTarget target;
    private final int replyTimeoutMillis;

    private DirectDelivery(ReplyServant servant, long instance, ReplyTarget target, int replyTimeoutMillis) {
        this.servant = servant;
        this.instance = instance;
        this.target = target;
        this.replyTimeoutMillis = replyTimeoutMillis;
    }

    /**
     * A direct sender for calls to {@code sink}'s host, or {@code null} when {@code sink} is not a JacORB
     * reference to another process (a peer in the same ORB is called in place, with nothing to save).
     */
    static DirectDelivery open(long link, ValueSink sink, Replies replies) {
        if (!(sink instanceof ObjectImpl stub) || !(stub._get_delegate() instanceof org.jacorb.orb.Delegate)
                || stub._is_local()) {
            return null;
        }
        try {
            ORB orb = stub._orb();
            ReplyServant servant = servantOf(orb);
            long instance = INSTANCES.incrementAndGet();
            servant.register(instance, new Outcomes(replies, link));
            ReplyTarget target = new ReplyTarget();
            org.omg.CORBA.Object reference = servant.poa.create_reference_with_id(idOf(instance), REPLY_HANDLER_ID);
            target._set_delegate(((ObjectImpl) reference)._get_delegate());
            return new DirectDelivery(servant, instance, target, replyTimeoutOf(orb));
        } catch (UserException | SystemException e) {
            LOG.warn("link values go through sender threads only: cannot set up direct delivery ({})", e.toString());
            return null;
        }
    }

    /** The ORB's reply servant, made with its POA on first use. */
    private static ReplyServant servantOf(ORB orb) throws UserException {
        synchronized (SERVANTS) {
            ReplyServant servant = SERVANTS.get(orb);
            if (servant == null) {
                POA root = POAHelper.narrow(orb.resolve_initial_references("RootPOA"));
                POA poa = root.create_POA("fdnet-direct-replies", root.the_POAManager(), new Policy[] {
                    root.create_request_processing_policy(RequestProcessingPolicyValue.USE_DEFAULT_SERVANT),
                    root.create_servant_retention_policy(ServantRetentionPolicyValue.NON_RETAIN),
                    root.create_id_assignment_policy(IdAssignmentPolicyValue.USER_ID),
                    root.create_id_uniqueness_policy(IdUniquenessPolicyValue.MULTIPLE_ID)});
                servant = new ReplyServant(poa, CurrentHelper.narrow(orb.resolve_initial_references("POACurrent")));
                poa.set_servant(servant);
                SERVANTS.put(orb, servant);
            }
            return servant;
        }
    }

    /** Forgets {@code orb}'s reply servant (the ORB is shut down: no reply can come to it any more). */
    static void orbClosed(ORB orb) {
        synchronized (SERVANTS) {
            SERVANTS.remove(orb);
        }
    }

    private static byte[] idOf(long instance) {
        return ByteBuffer.allocate(Long.BYTES).putLong(instance).array();
    }

    private static int replyTimeoutOf(ORB orb) {
        if (orb instanceof org.jacorb.orb.ORB jacorb) {
            try {
                return jacorb.getConfiguration().getAttributeAsInteger(REPLY_TIMEOUT, 0);
            } catch (org.jacorb.config.ConfigurationException e) {
                LOG.warn("{} is not a number of milliseconds: direct calls wait for their connection", REPLY_TIMEOUT);
            }
        }
        return 0;
    }

    /** How long a call may go without its reply before it counts as failed (0: as long as its connection lives). */
    int replyTimeoutMillis() {
        return replyTimeoutMillis;
    }

    /**
     * Writes the request and returns; the outcome comes to {@link Replies} later.
     *
     * @throws SystemException when the request cannot be sent (no connection, a closed ORB)
     */
    void send(ValueSink sink, ValueBatch batch) {
        ObjectImpl stub = (ObjectImpl) sink;
        for (int attempt = 0; ; attempt++) {
            OutputStream out = stub._request("deliver", true);
            try {
                ValueBatchHelper.write(out, batch);
                ((org.jacorb.orb.Delegate) stub._get_delegate()).invoke(stub, out, target);
                return;
            } catch (RemarshalException e) {
                if (attempt == MAX_REMARSHALS) {
                    throw new INTERNAL("deliver was redirected " + MAX_REMARSHALS + " times");
                }
            } catch (ApplicationException e) {
                throw new INTERNAL("an asynchronous deliver returned a reply at once: " + e.getId());
            }
        }
    }

    /** What a failed call says, the same words whether it was sent directly or by a sender thread. */
    static String failure(Exception e, long link) {
        if (e instanceof UnknownLink) {
            return "the peer does not know link " + link + " (it restarted and is not re-wired yet)";
        }
        return e.getClass().getSimpleName() + " " + e.getMessage();
    }

    /** From now on a reply to this instance's calls is dropped. */
    @Override
    public void close() {
        servant.forget(instance);
    }

    /** The reference JacORB calls back: a {@link ReplyHandler} whose servant is local. */
    private static final class ReplyTarget extends ObjectImpl implements ReplyHandler {
        @Override
        public String[] _ids() {
            return new String[] {REPLY_HANDLER_ID};
        }
    }

    /** Where one instance's replies go. */
    private record Outcomes(Replies replies, long link) {
    }

    /**
     * Reads the reply of {@code deliver} (or its exception holder) and hands the outcome to the instance the call
     * was made by, found by the object id the reply came to.
     */
    private static final class ReplyServant extends Servant implements InvokeHandler {
        private final POA poa;
        private final Current current;
        private final Map<Long, Outcomes> instances = new ConcurrentHashMap<>();

        ReplyServant(POA poa, Current current) {
            this.poa = poa;
            this.current = current;
        }

        void register(long instance, Outcomes outcomes) {
            instances.put(instance, outcomes);
        }

        void forget(long instance) {
            instances.remove(instance);
        }

        @Override
        public String[] _all_interfaces(POA poa, byte[] objectId) {
            return new String[] {REPLY_HANDLER_ID};
        }

        @Override
        public OutputStream _invoke(String operation, InputStream in, ResponseHandler handler) {
            Outcomes outcomes;
            try {
                outcomes = instances.get(ByteBuffer.wrap(current.get_object_id()).getLong());
            } catch (NoContext e) {
                LOG.warn("direct delivery: a reply came without its object id; dropped");
                return null;
            }
            if (outcomes == null) {
                LOG.debug("direct delivery: a reply to a call given up on; dropped");
                return null;
            }
            switch (operation) {
                case "deliver" -> outcomes.replies().replied(in.read_longlong());
                case "deliver_excep" -> outcomes.replies().failed(failureIn(in, outcomes.link()));
                default -> LOG.warn("direct delivery: unexpected reply to '{}'", operation);
            }
            return null;
        }

        private static String failureIn(InputStream in, long link) {
            try {
                ExceptionHolder holder = (ExceptionHolder) ((org.omg.CORBA_2_3.portable.InputStream) in).read_value();
                holder.raise_exception_with_list(new TypeCode[] {UnknownLinkHelper.type()});
                return "the peer answered with an exception that could not be read";
            } catch (UserException | SystemException e) {
                return failure(e, link);
            }
        }
    }
}

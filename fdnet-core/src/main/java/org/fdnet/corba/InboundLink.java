package org.fdnet.corba;

import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.atomic.AtomicLong;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.tls.Right;

/**
 * The receiving end of one cross-host link: applies batches to a local Data strictly in sequence order.
 * Batches may arrive out of order (several calls are in flight and JacORB serves them on a thread pool):
 * a batch ahead of the sequence waits here until the gap closes; values already applied (a sender
 * resending after a failure) are skipped, and so are values whose origin stream this host has already
 * applied at that number or later ({@link ValueOrigin}). The sender's window bounds what can wait.
 */
final class InboundLink {
    private static final long UNSET = -1;

    private final long id;
    private final NodeRef target;
    private final String fromHost;
    private final LocalNetwork network;
    /**
     * Per origin stream, the highest number applied to {@link #target}: shared by every link into it. A batch
     * holds one stream's consecutive numbers, so it looks its stream's mark up once and moves it per value.
     */
    private final Map<String, AtomicLong> seen;
    private final TreeMap<Long, ValueBatch> heldBack = new TreeMap<>();
    private long expected = UNSET;
    private long applied;
    private long duplicates;
    /** The last caller found allowed to write {@link #target}: a link's batches come from one peer, checked once. */
    private volatile String allowedWriter;

    InboundLink(long id, NodeRef target, String fromHost, LocalNetwork network, Map<String, AtomicLong> seen) {
        this.seen = seen;
        this.id = id;
        this.target = target;
        this.fromHost = fromHost;
        this.network = network;
    }

    long id() {
        return id;
    }

    NodeRef target() {
        return target;
    }

    /**
     * Fails the delivery unless {@code caller} may write this link's target Data.
     *
     * @throws org.omg.CORBA.NO_PERMISSION naming the certificate, the Data and the right
     */
    void requireWriter(String caller) {
        if (!caller.equals(allowedWriter)) {
            Caller.require(Right.WRITE, target);
            allowedWriter = caller;
        }
    }

    /** Applies what can be applied and returns the next sequence number expected. */
    synchronized long deliver(ValueBatch batch) {
        if (expected == UNSET) {
            expected = batch.firstSeq; // a fresh receiver: the sender sends its first batch alone
        }
        if (batch.firstSeq > expected) {
            heldBack.put(batch.firstSeq, batch);
            return expected;
        }
        apply(batch);
        while (!heldBack.isEmpty()) {
            long first = heldBack.firstKey();
            if (first > expected) {
                break;
            }
            apply(heldBack.remove(first));
        }
        return expected;
    }

    synchronized long applied() {
        return applied;
    }

    private void apply(ValueBatch batch) {
        long end = batch.firstSeq + batch.values.length;
        AtomicLong highest = seen.computeIfAbsent(batch.originStream, stream -> new AtomicLong(Long.MIN_VALUE));
        for (long seq = Math.max(expected, batch.firstSeq); seq < end; seq++) {
            int i = (int) (seq - batch.firstSeq);
            long originSeq = batch.originFirstSeq + i;
            if (originSeq <= highest.get()) {
                duplicates++; // came again through a relay that died after passing it on
                continue;
            }
            highest.set(originSeq);
            Object value = ValueCodec.decode(batch.values[i]);
            network.inject(target, value, fromHost, new ValueOrigin(batch.originStream, originSeq));
            applied++;
        }
        expected = Math.max(expected, end);
    }

    synchronized long duplicates() {
        return duplicates;
    }
}

package org.fdnet.corba;

import java.util.TreeMap;
import org.fdnet.corba.idl.ValueBatch;
import org.fdnet.netinfo.NodeRef;

/**
 * The receiving end of one cross-host link: applies batches to a local Data strictly in sequence order.
 * Batches may arrive out of order (several calls are in flight and JacORB serves them on a thread pool):
 * a batch ahead of the sequence waits here until the gap closes; values already applied (a sender
 * resending after a failure) are skipped. The sender's window bounds what can wait.
 */
final class InboundLink {
    private static final long UNSET = -1;

    private final long id;
    private final NodeRef target;
    private final String fromHost;
    private final LocalNetwork network;
    private final TreeMap<Long, ValueBatch> heldBack = new TreeMap<>();
    private long expected = UNSET;
    private long applied;

    InboundLink(long id, NodeRef target, String fromHost, LocalNetwork network) {
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
        for (long seq = Math.max(expected, batch.firstSeq); seq < end; seq++) {
            network.inject(target, ValueCodec.decode(batch.values[(int) (seq - batch.firstSeq)]), fromHost);
            applied++;
        }
        expected = Math.max(expected, end);
    }
}

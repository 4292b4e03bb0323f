package org.fdnet.testing;

import java.util.List;
import java.util.Map;
import java.util.concurrent.BlockingQueue;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.LinkedBlockingQueue;
import java.util.concurrent.TimeUnit;
import org.fdnet.control.LiveNetworkListener;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Value;

/** What a live network told its subscriber, kept in queues a test can wait on. */
public final class HeardFromNetwork implements LiveNetworkListener {
    public final BlockingQueue<ChangeOutcome> changes = new LinkedBlockingQueue<>();
    public final BlockingQueue<Map<NodeRef, Value>> samples = new LinkedBlockingQueue<>();
    public final List<String> disconnects = new CopyOnWriteArrayList<>();

    @Override
    public void changeSettled(ChangeOutcome outcome) {
        changes.add(outcome);
    }

    @Override
    public void valuesSampled(Map<NodeRef, Value> latest) {
        samples.add(latest);
    }

    @Override
    public void disconnected(String reason) {
        disconnects.add(reason);
    }

    /** Waits (at most 15 s) for a sample that contains {@code data}. */
    public boolean sampleWith(NodeRef data) throws InterruptedException {
        return sampleWith(data, 15_000);
    }

    /** Waits at most {@code millis} for a sample that contains {@code data}, dropping the samples before it. */
    public boolean sampleWith(NodeRef data, long millis) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.MILLISECONDS.toNanos(millis);
        while (System.nanoTime() < deadline) {
            Map<NodeRef, Value> s = samples.poll(100, TimeUnit.MILLISECONDS);
            if (s != null && s.containsKey(data)) {
                return true;
            }
        }
        return false;
    }

    /** Waits (at most 15 s) for a settled change whose description contains {@code text}; {@code null} if none came. */
    public ChangeOutcome changeAbout(String text) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(15);
        while (System.nanoTime() < deadline) {
            ChangeOutcome o = changes.poll(100, TimeUnit.MILLISECONDS);
            if (o != null && o.description().contains(text)) {
                return o;
            }
        }
        return null;
    }
}

package org.fdnet.corba;

import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.RejectedExecutionException;
import java.util.concurrent.ThreadPoolExecutor;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.ArrayBlockingQueue;
import org.fdnet.corba.idl.ChangeKind;
import org.fdnet.corba.idl.NetworkChange;
import org.fdnet.corba.idl.NetworkListener;
import org.omg.CORBA.SystemException;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Tells every subscribed {@link NetworkListener} about the host's structural changes. Each listener has
 * one thread and a bounded queue of its own, so a slow or dead listener never stalls the host or the
 * others; a listener whose call fails is dropped (it subscribes again when it comes back).
 */
final class ChangeNotifier implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(ChangeNotifier.class);
    private static final int QUEUE = 10_000;

    private final String hostName;
    private final Map<String, Subscriber> subscribers = new ConcurrentHashMap<>();

    ChangeNotifier(String hostName) {
        this.hostName = hostName;
    }

    private record Subscriber(NetworkListener listener, ExecutorService thread) {
    }

    void subscribe(NetworkListener listener, String key) {
        ExecutorService thread = new ThreadPoolExecutor(1, 1, 0, TimeUnit.MILLISECONDS,
                new ArrayBlockingQueue<>(QUEUE), r -> {
                    Thread t = new Thread(r, "fdnet-notify-" + hostName);
                    t.setDaemon(true);
                    return t;
                });
        Subscriber old = subscribers.put(key, new Subscriber(listener, thread));
        if (old != null) {
            old.thread.shutdown();
        }
    }

    void unsubscribe(String key) {
        Subscriber old = subscribers.remove(key);
        if (old != null) {
            old.thread.shutdown();
        }
    }

    void publish(ChangeKind kind, String subject) {
        NetworkChange change = new NetworkChange(kind, hostName, subject,
                System.currentTimeMillis() * 1000L);
        subscribers.forEach((key, s) -> {
            try {
                s.thread.execute(() -> tell(key, s, change));
            } catch (RejectedExecutionException e) {
                LOG.warn("listener {} is {} changes behind; dropping it", key, QUEUE);
                unsubscribe(key);
            }
        });
    }

    private void tell(String key, Subscriber s, NetworkChange change) {
        try {
            s.listener.changed(change);
        } catch (SystemException e) {
            LOG.info("listener {} is gone ({}); dropping it", key, e.getClass().getSimpleName());
            unsubscribe(key);
        }
    }

    @Override
    public void close() {
        subscribers.values().forEach(s -> s.thread.shutdownNow());
        subscribers.clear();
    }
}

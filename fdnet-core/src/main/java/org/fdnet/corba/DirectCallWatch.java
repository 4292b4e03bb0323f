package org.fdnet.corba;

import java.util.Set;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.Executors;
import java.util.concurrent.ScheduledExecutorService;
import java.util.concurrent.TimeUnit;

/**
 * Fails direct calls ({@link DirectDelivery}) whose reply is overdue. A blocking call times out on the thread that
 * waits for it; a direct call has no such thread — its writer went on at once — so one daemon thread per process
 * looks at every link that sends directly every {@value #PERIOD_MILLIS} ms, and a call is failed at most that long
 * after its reply timeout.
 */
final class DirectCallWatch {
    /** How often the links are looked at: the most a failed call's detection lags behind the reply timeout. */
    static final long PERIOD_MILLIS = 100;

    private static final Set<OutboundLink> LINKS = ConcurrentHashMap.newKeySet();
    private static ScheduledExecutorService thread;

    private DirectCallWatch() {
    }

    static synchronized void watch(OutboundLink link) {
        LINKS.add(link);
        if (thread == null) {
            thread = Executors.newSingleThreadScheduledExecutor(r -> {
                Thread t = new Thread(r, "fdnet-direct-call-watch");
                t.setDaemon(true);
                return t;
            });
            thread.scheduleWithFixedDelay(DirectCallWatch::lookAtAll, PERIOD_MILLIS, PERIOD_MILLIS, TimeUnit.MILLISECONDS);
        }
    }

    static void forget(OutboundLink link) {
        LINKS.remove(link);
    }

    private static void lookAtAll() {
        for (OutboundLink link : LINKS) {
            link.settleOverdueDirectCall();
        }
    }
}

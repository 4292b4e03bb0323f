package org.fdnet.hi.live;

import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.function.BooleanSupplier;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.runtime.engine.RuntimeStartException;
import org.fdnet.testing.OnEdt;

/**
 * The network the live tests run in their own JVM: module Wave (a 50 ms sine into Wave/signal), main/Gain
 * (2 * in0) writing main/Out, and main/Organizer, an AutoFilter that gives every DoubleSensor a filter by
 * itself. Plus the waiting the tests need: on the Swing thread, until a condition holds (10 s at most).
 */
public final class LiveTestNetwork {
    public static final String LIB = "org.fdnet.runtime.library.";

    private LiveTestNetwork() {
    }

    public static NodeRef ref(String text) {
        return NodeRef.parse(text, "main");
    }

    public static NetworkInfo definition() {
        NetworkInfo n = new NetworkInfo("live-editor-test");
        n.addModule("Wave", true);
        n.addNode("Wave", NodeInfo.data("signal", LIB + "DoubleData"));
        n.addNode("Wave", NodeInfo.relation("source", LIB + "PeriodicSource", Parameter.named("period", "50")));
        n.addConnection("Wave", ConnectionInfo.writer(ref("Wave/source"), ref("Wave/signal")));
        n.addNode("main", NodeInfo.data("Out", LIB + "DoubleData"));
        n.addNode("main", NodeInfo.relation("Gain", LIB + "Expression", Parameter.named("expression", "2 * in0")));
        n.addConnection("main", ConnectionInfo.reader(ref("Wave/signal"), ref("Gain")));
        n.addConnection("main", ConnectionInfo.writer(ref("Gain"), ref("Out")));
        n.addNode("main", NodeInfo.relation("Organizer", LIB + "AutoFilter", Parameter.named("period", "20")));
        return n;
    }

    public static InProcessRun start() throws RuntimeStartException {
        return InProcessRun.start(definition(), RuntimeOptions.defaults().workerThreads(2));
    }

    /** Calls on the Swing thread ({@link OnEdt}). */
    public static <T> T edt(Callable<T> call) throws Exception {
        return OnEdt.call(call);
    }

    /** Waits, checking on the Swing thread, until {@code condition} holds; false after 10 s. */
    public static boolean eventually(BooleanSupplier condition) throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (System.nanoTime() < deadline) {
            if (edt(condition::getAsBoolean)) {
                return true;
            }
            Thread.sleep(50);
        }
        return false;
    }
}

package org.fdnet.runtime;

import java.util.concurrent.TimeUnit;
import org.fdnet.event.MemoryEventSink;
import org.fdnet.netinfo.ConnectionInfo;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.NodeInfo;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.Parameter;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.runtime.engine.RuntimeStartException;

/** Small builders for the runtime's tests: networks are built in code, not read from files. */
final class TestNetworks {
    private TestNetworks() {
    }

    static final String LIB = "org.fdnet.runtime.library.";

    static NodeRef ref(String text) {
        return NodeRef.parse(text, "main");
    }

    static NodeInfo data(String name, String cls, String... params) {
        return NodeInfo.data(name, cls.contains(".") ? cls : LIB + cls, parameters(params));
    }

    static NodeInfo relation(String name, String cls, String... params) {
        return NodeInfo.relation(name, cls.contains(".") ? cls : LIB + cls, parameters(params));
    }

    /** "name=value" pairs. */
    static Parameter[] parameters(String... pairs) {
        Parameter[] ps = new Parameter[pairs.length];
        for (int i = 0; i < pairs.length; i++) {
            int eq = pairs[i].indexOf('=');
            ps[i] = Parameter.named(pairs[i].substring(0, eq), pairs[i].substring(eq + 1));
        }
        return ps;
    }

    /** A Reader declared by {@code module}; bare names mean the module's node, else main's (as in files). */
    static void read(NetworkInfo n, String module, String data, String relation) {
        n.addConnection(module, ConnectionInfo.reader(resolve(n, module, data), resolve(n, module, relation)));
    }

    static void write(NetworkInfo n, String module, String relation, String data) {
        n.addConnection(module, ConnectionInfo.writer(resolve(n, module, relation), resolve(n, module, data)));
    }

    private static NodeRef resolve(NetworkInfo n, String module, String name) {
        NodeRef r = n.resolve(module, name);
        return r != null ? r : NodeRef.parse(name, module);
    }

    /** Options for tests: test classes (in org.fdnet.runtime) count as built in. */
    static RuntimeOptions options() {
        return RuntimeOptions.defaults().workerThreads(2)
                .classLoading(org.fdnet.runtime.loading.ClassLoadingPolicy.builtInOnly().withBuiltInPackage("org.fdnet.runtime."));
    }

    static RuntimeNetwork start(NetworkInfo n, MemoryEventSink sink) throws RuntimeStartException {
        RuntimeOptions o = options();
        if (sink != null) {
            o.sink(sink);
        }
        return RuntimeNetwork.start(n, o);
    }

    static void quiet(RuntimeNetwork net) throws InterruptedException {
        if (!net.awaitQuiet(10, TimeUnit.SECONDS)) {
            throw new AssertionError("the network did not settle in 10 s");
        }
    }

    /** Polls until the condition holds or 10 s pass. */
    static void eventually(String what, java.util.function.BooleanSupplier condition) throws InterruptedException {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > deadline) {
                throw new AssertionError("timed out waiting for: " + what);
            }
            Thread.sleep(5);
        }
    }
}

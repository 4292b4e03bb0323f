package org.fdnet.corba;

import java.nio.file.Path;
import java.util.List;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.runtime.loading.ClassLoadingPolicy;

/** Chooses the engine behind a host: the one place that knows which {@link LocalNetwork} a host runs. */
public final class LocalNetworks {
    private LocalNetworks() {
    }

    /**
     * The single-host engine for host {@code hostName}: it loads built-in classes and classes under
     * {@code allowedPaths} only (the same rule {@link ClassPolicy} checks before a remote create).
     */
    public static RuntimeLocalNetwork forHost(String hostName, List<Path> allowedPaths) {
        return forHost(hostName, allowedPaths, RuntimeOptions.defaults());
    }

    /** As above, with {@code options}' worker threads and sinks (fdnet host --workers; a run's own host: --trace). */
    public static RuntimeLocalNetwork forHost(String hostName, List<Path> allowedPaths, RuntimeOptions options) {
        ClassLoadingPolicy policy = new ClassLoadingPolicy(allowedPaths, ClassPolicy.BUILT_IN_PACKAGES,
                Path.of("").toAbsolutePath());
        return RuntimeLocalNetwork.start(hostName, options.classLoading(policy));
    }
}

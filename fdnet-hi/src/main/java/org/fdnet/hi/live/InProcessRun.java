package org.fdnet.hi.live;

import java.nio.file.Path;
import java.util.List;
import org.fdnet.control.LiveNetwork;
import org.fdnet.control.LocalLiveNetwork;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.netinfo.xml.NetworkFileException;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.runtime.engine.RuntimeStartException;
import org.fdnet.runtime.loading.ClassLoadingPolicy;

/**
 * A network run in the editor's own process ({@code fdnet hi --run FILE}): started from its file as
 * {@code fdnet run} starts it on one host, and offered to the editor as a {@link LiveNetwork}. Closing it stops
 * the network, and an attached editor is told so (it stays open offline).
 */
public final class InProcessRun implements AutoCloseable {
    private final RuntimeNetwork network;
    private final LocalLiveNetwork live;

    private InProcessRun(RuntimeNetwork network, LocalLiveNetwork live) {
        this.network = network;
        this.live = live;
    }

    /** Starts {@code definition}, whose node classes are looked up as for a network file in {@code directory}. */
    public static InProcessRun start(NetworkInfo definition, RuntimeOptions options) throws RuntimeStartException {
        return start(definition, options, java.util.Optional.empty());
    }

    /** As {@link #start(NetworkInfo, RuntimeOptions)}, recorded by the logger whose viewers connect to {@code loggerViewer}. */
    public static InProcessRun start(NetworkInfo definition, RuntimeOptions options,
                                     java.util.Optional<String> loggerViewer) throws RuntimeStartException {
        RuntimeNetwork network = RuntimeNetwork.start(definition, options);
        String name = definition.name() == null ? "unnamed" : definition.name();
        return new InProcessRun(network, new LocalLiveNetwork(name, network.controller(), loggerViewer));
    }

    /** Reads and starts {@code file} (classes from the library, the RoQ's and the file's own directory). */
    public static InProcessRun start(Path file) throws NetworkFileException, RuntimeStartException {
        return start(NetworkRepository.load(file),
                RuntimeOptions.defaults().classLoading(ClassLoadingPolicy.forNetworkFile(file, List.of())));
    }

    public LiveNetwork live() {
        return live;
    }

    public RuntimeNetwork network() {
        return network;
    }

    @Override
    public void close() {
        live.networkStopped("the network was stopped");
        network.close();
    }
}

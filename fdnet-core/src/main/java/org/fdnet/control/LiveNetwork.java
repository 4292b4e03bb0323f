package org.fdnet.control;

import java.util.Optional;
import java.util.Set;
import org.fdnet.netinfo.NetworkInfo;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.NetworkControl;

/**
 * A running network as an operator's tool sees it — the editor attached to it, a deploy preview, a script —
 * whether it runs in this process or is reached through its CORBA control object.
 *
 * <p>Every change is a change request of the network: executed everywhere it applies, or refused with its
 * reason and nothing changed. A tool shows a change only once it was executed.
 */
public interface LiveNetwork extends NetworkControl, AutoCloseable {
    /** The network's name, as it is published. */
    String name();

    /** The running network as a definition, including every node and connection it built itself. A copy. */
    NetworkInfo snapshot();

    Set<String> loadedModules();

    Set<String> heldModules();

    /**
     * Makes the running network change as {@code base} was changed into {@code edited}: the difference
     * (modules, nodes, parameters and connections added, removed or changed) is applied to the running
     * definition as one change request, all of it or none. Changes the network made since {@code base}
     * are kept; a difference that no longer fits them is refused with the reason.
     */
    default ChangeOutcome apply(String description, NetworkInfo base, NetworkInfo edited) {
        NetworkDiff diff = NetworkDiff.between(base, edited);
        if (diff.isEmpty()) {
            return ChangeOutcome.executed(description + " (no changes)");
        }
        return apply(description, diff.asEdit());
    }

    /**
     * Where viewers reach the logger that records this run ({@code HOST:PORT} of its viewer service), when the run
     * knows it: {@code fdnet demo} with its embedded logger, {@code fdnet run --logger-viewer}. Empty otherwise (the
     * logger protocol does not tell a core its viewer port).
     */
    default Optional<String> loggerViewerAddress() {
        return Optional.empty();
    }

    /** Subscribes to settled changes and to sampled live values; close the handle to stop. */
    AutoCloseable subscribe(LiveNetworkListener listener);

    /** Lets go of the network; it keeps running. */
    @Override
    void close();
}

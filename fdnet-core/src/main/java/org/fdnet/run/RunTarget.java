package org.fdnet.run;

import java.io.PrintWriter;
import java.util.Map;
import org.fdnet.control.LiveNetwork;
import org.fdnet.corba.control.ControlPublication;
import org.fdnet.runtime.NetworkControl;
import org.fdnet.runtime.engine.RuntimeNetwork;

/**
 * What a {@link NetworkRun} runs on: this process's engine alone ({@link LocalTarget}) or a deployment over
 * several hosts ({@link DistributedTarget}). The run's life is the same for both; only these differ.
 */
interface RunTarget {
    /** Every change of the run goes through it: --load, --set, --param, standard-input commands. */
    NetworkControl control();

    /** This process's engine (the whole network, or this process's host's share of it). */
    RuntimeNetwork engine();

    /** The run as a live network named {@code name}, for its control object. */
    LiveNetwork live(String name);

    /**
     * Publishes {@code live} where this kind of run publishes it and prints where; {@code null} when it is not.
     *
     * @throws IllegalArgumentException naming the option that places it where it cannot be
     */
    ControlPublication publish(LiveNetwork live, PrintWriter out);

    /** What this kind of run adds to the status line (may be empty). */
    String status();

    /** What this kind of run adds to the summary. */
    void summary(PrintWriter out);

    /** Stops the run everywhere; what the logger committed of it, by host (empty without a logger). */
    Map<String, String> stop();
}

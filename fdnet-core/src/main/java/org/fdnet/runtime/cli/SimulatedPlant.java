package org.fdnet.runtime.cli;

import java.io.PrintWriter;
import org.fdnet.runtime.engine.RuntimeNetwork;

/**
 * A simulated plant {@code fdnet run FILE --sim COURSE} can join a running network to, found through
 * {@code META-INF/services/org.fdnet.runtime.cli.SimulatedPlant} so that the core does not depend on the part that
 * provides it (roq-sim provides RoQ's simulator).
 */
public interface SimulatedPlant {
    /**
     * Joins the started {@code network} to the plant on {@code course} in real time; returns the run, which
     * {@link Run#close()} stops (before the network is closed). Throws {@link IllegalArgumentException} with a
     * message naming what is wrong (unknown course, network without the plant's nodes).
     */
    Run attach(RuntimeNetwork network, String course, PrintWriter out);

    /** A plant joined to a network. */
    interface Run extends AutoCloseable {
        /** A short status for the progress line, e.g. "sim t=12.0 s, x=0.40 m". */
        String status();

        /** A line for the summary. */
        String summary();

        @Override
        void close();
    }
}

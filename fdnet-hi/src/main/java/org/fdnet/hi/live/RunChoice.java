package org.fdnet.hi.live;

import org.fdnet.run.RunOptions;

/**
 * Where the editor runs the open network (Live → Run): on this machine, distributed through the naming service at
 * {@code naming} (when its nodes name other hosts), or joined to the simulated RoQ on {@code course}; recorded by
 * the logger at {@code logger} ({@code HOST:PORT}) when one is given.
 */
public record RunChoice(Where where, String naming, String course, String logger) {
    /** The three places a network can run from the editor. */
    public enum Where { THIS_MACHINE, DISTRIBUTED, SIMULATED_ROQ }

    public static RunChoice thisMachine() {
        return new RunChoice(Where.THIS_MACHINE, "", "", "");
    }

    public static RunChoice distributed(String naming) {
        return new RunChoice(Where.DISTRIBUTED, naming, "", "");
    }

    public static RunChoice simulated(String course) {
        return new RunChoice(Where.SIMULATED_ROQ, "", course, "");
    }

    public RunChoice withLogger(String address) {
        return new RunChoice(where, naming, course, address == null ? "" : address.trim());
    }

    /** The run's options, as {@code fdnet run} would take them. */
    public RunOptions options() {
        RunOptions options = RunOptions.defaults();
        if (where == Where.DISTRIBUTED) {
            options.naming(naming);
        } else if (where == Where.SIMULATED_ROQ) {
            options.sim(course);
        }
        if (!logger.isEmpty()) {
            options.logger(logger);
        }
        return options;
    }

    /** How the status bar says where it runs. */
    public String describe() {
        return switch (where) {
            case THIS_MACHINE -> "on this machine";
            case DISTRIBUTED -> "over its hosts (naming service " + naming + ")";
            case SIMULATED_ROQ -> "on the simulated RoQ (course " + course + ")";
        };
    }
}

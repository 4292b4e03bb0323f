package org.fdnet.runtime;

import org.fdnet.netinfo.ConnectionInfo;

/**
 * A live connection with one end on another host (see {@link Placement}). The engine never crashes on
 * one: it keeps a local stand-in for a remote Data (which the distribution layer feeds through
 * {@link Controller#setValue} and observes through {@link Controller#observe}), or, for a remote
 * Relation, leaves the local Data to be observed and fed the same way.
 *
 * @param connection  the declared connection
 * @param remoteEnd   which end lives elsewhere: "data" or "relation"
 * @param remoteHost  that end's host
 * @param standIn     whether a local stand-in Data was made for it
 * @param problem     why the link is broken (e.g. the stand-in's class could not be loaded), or {@code null}
 */
public record RemoteLink(ConnectionInfo connection, String remoteEnd, String remoteHost, boolean standIn,
                         String problem) {
    /**
     * Whether the link cannot carry values.
     *
     * @return true when {@link #problem()} says why
     */
    public boolean broken() {
        return problem != null;
    }
}

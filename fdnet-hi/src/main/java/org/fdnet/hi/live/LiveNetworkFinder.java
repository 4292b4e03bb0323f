package org.fdnet.hi.live;

import org.fdnet.control.LiveNetwork;

/** Finds a running network by the name it is published under (or its address), for Attach and Deploy. */
@FunctionalInterface
public interface LiveNetworkFinder {
    /**
     * @throws org.fdnet.control.NetworkUnreachableException naming the network and where it was looked for, when
     *         it cannot be reached
     */
    LiveNetwork find(String nameOrAddress);
}

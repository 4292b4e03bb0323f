package org.fdnet.runtime;

import org.fdnet.netinfo.NodeRef;

/**
 * Sees every value a Data takes, in the order the Data takes them (the seam a distribution layer uses to
 * forward a Data's values to other hosts, and the editor to show them). Called while the network's
 * commit lock is held so that the order is the Data's own: enqueue and return — never block, never
 * call back into the network. An exception is logged and the observer stays registered.
 */
@FunctionalInterface
public interface DataValueObserver {
    /**
     * {@code value} carries its timestamp ({@link Value#time()}), unique and increasing for this Data.
     *
     * @param data   the Data that took the value
     * @param dataId the id its events carry ({@link Controller#nodeId})
     * @param value  the committed, stamped value
     */
    void valueChanged(NodeRef data, int dataId, Value value);
}

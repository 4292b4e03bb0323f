package org.fdnet.control;

import java.util.List;
import java.util.concurrent.CopyOnWriteArrayList;

/** The subscribers of one {@link LiveNetwork}: each its own {@link LiveSubscription} on the same sampled network. */
public final class LiveSubscriptions {
    private final String networkName;
    private final SampledNetwork network;
    private final List<LiveSubscription> subscriptions = new CopyOnWriteArrayList<>();

    public LiveSubscriptions(String networkName, SampledNetwork network) {
        this.networkName = networkName;
        this.network = network;
    }

    /** Starts telling {@code listener} the network's settled changes and sampled values; close the handle to stop. */
    public AutoCloseable open(LiveNetworkListener listener) {
        LiveSubscription s = new LiveSubscription(networkName, network, listener, subscriptions::remove);
        subscriptions.add(s);
        s.start();
        return s;
    }

    /** Tells every subscriber that the network stopped ({@code disconnected(reason)}, their last call). */
    public void networkStopped(String reason) {
        for (LiveSubscription s : subscriptions) {
            s.disconnect(reason);
        }
    }

    /** Ends every subscription; the network keeps running. */
    public void closeAll() {
        for (LiveSubscription s : subscriptions) {
            s.close();
        }
    }
}

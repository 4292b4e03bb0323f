package org.fdnet.control;

import java.util.List;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeListener;
import org.fdnet.runtime.Value;

/**
 * What a {@link LiveSubscription} listens to and samples: a network's settled changes and its Datas' latest values.
 * A local run's {@code Controller} gives all of it; a run across hosts reads each Data from its home host.
 */
public interface SampledNetwork {
    void addChangeListener(ChangeListener listener);

    void removeChangeListener(ChangeListener listener);

    /**
     * The Data's latest value, or {@code null} when it is not running. The same object until the Data is written
     * again: the sampler reports a Data when its value object changed.
     */
    Value value(NodeRef data);

    /** The Datas running now; asked again after every settled change. */
    List<NodeRef> runningDatas();
}

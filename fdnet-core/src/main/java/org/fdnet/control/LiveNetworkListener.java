package org.fdnet.control;

import java.util.Map;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.runtime.ChangeOutcome;
import org.fdnet.runtime.Value;

/** What a {@link LiveNetwork} tells its subscribers, on a thread of its own (never the Swing thread). */
public interface LiveNetworkListener {
    /** A change request settled, whoever made it: an operator, an editor, a Relation through its Servants. */
    void changeSettled(ChangeOutcome outcome);

    /** The latest value of each Data written since the previous call; sampled, at most ten calls a second. */
    void valuesSampled(Map<NodeRef, Value> latest);

    /** The network stopped or cannot be reached any more; no call follows this one. */
    void disconnected(String reason);
}

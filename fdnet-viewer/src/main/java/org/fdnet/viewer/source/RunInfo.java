package org.fdnet.viewer.source;

import java.util.List;
import org.fdnet.event.wire.LoggedNode;

/** A run the logger recorded (its {@code run_id}) and the Data nodes it named. */
public record RunInfo(int runId, List<LoggedNode> nodes) {
    public int[] sourceIds() {
        return nodes.stream().mapToInt(LoggedNode::sourceId).toArray();
    }

    @Override
    public String toString() {
        return "run " + runId + " (" + nodes.size() + " Datas)";
    }
}

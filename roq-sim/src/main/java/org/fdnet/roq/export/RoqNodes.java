package org.fdnet.roq.export;

import java.util.Optional;
import org.fdnet.logger.export.RecordedNode;
import org.fdnet.logger.export.RecordedRun;

/**
 * The source ids of the Datas a RoQ network records that the 3D scene is drawn from ({@code main/body position},
 * {@code main/attitude}, {@code main/joint angles}, {@code main/foot forces}, and {@code Course/heading} when the
 * network has it; -1 where absent). A run without body position and joint angles is not a RoQ run.
 */
record RoqNodes(int position, int attitude, int angles, int forces, int heading) {
    static Optional<RoqNodes> of(RecordedRun run) {
        RoqNodes n = new RoqNodes(id(run, "main/body position"), id(run, "main/attitude"), id(run, "main/joint angles"),
                id(run, "main/foot forces"), id(run, "Course/heading"));
        return n.position >= 0 && n.angles >= 0 ? Optional.of(n) : Optional.empty();
    }

    private static int id(RecordedRun run, String label) {
        for (RecordedNode n : run.nodes().values()) {
            if (n.label().equals(label)) {
                return n.sourceId();
            }
        }
        return -1;
    }
}

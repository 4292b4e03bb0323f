package org.fdnet.roq.export;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.fdnet.logger.export.RecordedRun;
import org.fdnet.logger.export.RunScene;
import org.fdnet.logger.export.SceneSource;
import org.fdnet.roq.sim.CourseFormatException;
import org.fdnet.roq.sim.CourseLoader;
import org.fdnet.roq.sim.FragileCell;

/**
 * Offers RoQ's 3D scene for a run that recorded RoQ's body position and joint angles. Option {@code course} (a
 * built-in course's name or a course file, as {@code fdnet demo --course} takes) adds its fragile cells; an unknown
 * course is refused with the loader's message.
 */
public final class RoqSceneSource implements SceneSource {
    @Override
    public Optional<RunScene> sceneOf(RecordedRun run, Map<String, String> options) {
        Optional<RoqNodes> nodes = RoqNodes.of(run);
        if (nodes.isEmpty()) {
            return Optional.empty();
        }
        List<FragileCell> cells = List.of();
        String course = options.get("course");
        if (course != null) {
            try {
                cells = CourseLoader.resolve(course).fragileCells();
            } catch (CourseFormatException e) {
                throw new IllegalArgumentException("--scene course=" + course + ": " + e.getMessage(), e);
            }
        }
        return Optional.of(new RoqScene(nodes.get(), cells));
    }
}

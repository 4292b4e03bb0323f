package org.fdnet.logger.export;

import java.util.Optional;

/**
 * A part of FDNet that knows how to draw a kind of run in 3D (roq-sim draws RoQ): given the run, it offers a
 * {@link RunScene} when the run is one of its kind. Found with {@link java.util.ServiceLoader}: list an
 * implementation in {@code META-INF/services/org.fdnet.logger.export.SceneSource}.
 */
public interface SceneSource {
    Optional<RunScene> sceneOf(RecordedRun run);
}

package org.fdnet.logger.export;

import java.util.Optional;

/**
 * A part of FDNet that knows how to draw a kind of run in 3D (roq-sim draws RoQ): given the run and the export's
 * scene options ({@code fdnet export --scene KEY=VALUE}), it offers a {@link RunScene} when the run is one of its
 * kind; an option it cannot use is refused with an {@link IllegalArgumentException} naming it. Found with {@link java.util.ServiceLoader}: list an
 * implementation in {@code META-INF/services/org.fdnet.logger.export.SceneSource}.
 */
public interface SceneSource {
    Optional<RunScene> sceneOf(RecordedRun run, java.util.Map<String, String> options);
}

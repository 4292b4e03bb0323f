package org.fdnet.logger.writer;

import java.util.List;
import org.fdnet.logger.cache.CachedEvent;

/** Told of every batch right after its commit, on the writer's thread (measurements: keep it short). */
@FunctionalInterface
public interface BatchObserver {
    void committed(List<CachedEvent> batch);
}

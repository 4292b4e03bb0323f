package org.fdnet.logger.export;

import java.util.List;

/**
 * Extra MCAP topics derived from a run's rows, in Foxglove's well-known schemas (e.g. {@code foxglove.SceneUpdate}):
 * the export declares {@link #topics()}, then hands every row in time order to {@link #accept}, which emits
 * messages at or after that row's time through {@link Out}; {@link #finish} may emit the last ones.
 */
public interface RunScene {
    /** A derived topic: its name, its schema's name and JSON Schema. */
    record Topic(String topic, String schemaName, String jsonSchema) {
    }

    /** Where a scene's messages go: the index of its topic in {@link #topics()}, a log time in ns, the JSON body. */
    interface Out {
        void emit(int topic, long logTimeNanos, String json) throws java.io.IOException;
    }

    List<Topic> topics();

    void accept(ExportRow row, Out out) throws java.io.IOException;

    default void finish(Out out) throws java.io.IOException {
    }
}

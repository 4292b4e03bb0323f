package org.fdnet.logger.export;

import java.io.Closeable;
import java.io.IOException;

/**
 * Where an export's rows go (an MCAP file, a long or a wide CSV table): {@link #begin} once with the run, then
 * every row in time order, then {@link #close}, which completes the file.
 */
public interface RunSink extends Closeable {
    void begin(RecordedRun run) throws IOException;

    void accept(ExportRow row) throws IOException;

    /** Records (messages, CSV lines) written so far. */
    long written();

    /** Channels (MCAP) or value columns (CSV) so far. */
    int channels();

    /** Bytes of the file so far (all of it once closed). */
    long bytes();
}

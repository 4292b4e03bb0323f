package org.fdnet.logger.export;

import java.io.BufferedWriter;
import java.io.IOException;
import java.io.OutputStream;
import java.io.OutputStreamWriter;
import java.nio.charset.StandardCharsets;

/** What the CSV sinks share: UTF-8 text through a buffer, the lines written and the bytes counted. */
abstract class CsvSink implements RunSink {
    private final CountingOutput counted;
    final BufferedWriter out;
    long lines;

    CsvSink(OutputStream stream) {
        this.counted = new CountingOutput(stream);
        this.out = new BufferedWriter(new OutputStreamWriter(counted, StandardCharsets.UTF_8), 1 << 16);
    }

    @Override
    public long written() {
        return lines;
    }

    @Override
    public long bytes() {
        return counted.count();
    }

    @Override
    public void close() throws IOException {
        out.close();
    }
}

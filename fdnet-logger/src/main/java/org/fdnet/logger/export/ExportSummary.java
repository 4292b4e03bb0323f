package org.fdnet.logger.export;

/** What an export wrote: rows read, records written (messages or lines), channels or columns, bytes, seconds. */
public record ExportSummary(long rows, long records, int channels, long bytes, double seconds) {
    public double rowsPerSecond() {
        return seconds > 0 ? rows / seconds : 0;
    }

    @Override
    public String toString() {
        return String.format("%,d rows → %,d records, %,d channels, %,d bytes in %.2f s (%,.0f rows/s)",
                rows, records, channels, bytes, seconds, rowsPerSecond());
    }
}

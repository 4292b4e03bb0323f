package org.fdnet.logger.export;

import java.util.zip.CRC32;

/**
 * The chunk being filled: its records uncompressed, the time span of its messages and, per channel, the
 * message index (each message's log time and offset within the uncompressed records) that follows the chunk
 * in the file. Emptied and reused after each chunk is written.
 */
final class McapChunk {
    private final RecordBuffer records = new RecordBuffer(1 << 20);
    /** Per channel id: its message index entries in this chunk, null where it has none yet. */
    private RecordBuffer[] index = new RecordBuffer[16];
    private final int[] touched = new int[McapWriter.MAX_CHANNELS];
    private int touchedCount;
    private long startTime = Long.MAX_VALUE;
    private long endTime = Long.MIN_VALUE;
    private int messages;

    /** A schema or channel record (the spec lets them precede their messages inside a chunk). */
    void record(int opcode, RecordBuffer content) {
        records.u8(opcode).u64(content.length()).raw(content);
    }

    void message(int channel, long sequence, long logTime, byte[] data, int off, int n) {
        long offset = records.length();
        records.u8(McapWriter.OP_MESSAGE).u64(2 + 4 + 8 + 8 + n)
                .u16(channel).u32(sequence).u64(logTime).u64(logTime).raw(data, off, n);
        if (channel >= index.length) {
            index = java.util.Arrays.copyOf(index, Math.max(channel + 1, index.length * 2));
        }
        RecordBuffer entries = index[channel];
        if (entries == null) {
            entries = new RecordBuffer(256);
            index[channel] = entries;
        }
        if (entries.length() == 0) {
            touched[touchedCount++] = channel;
        }
        entries.u64(logTime).u64(offset);
        startTime = Math.min(startTime, logTime);
        endTime = Math.max(endTime, logTime);
        messages++;
    }

    boolean isEmpty() {
        return records.length() == 0;
    }

    int uncompressedSize() {
        return records.length();
    }

    RecordBuffer records() {
        return records;
    }

    long crc() {
        CRC32 crc = new CRC32();
        crc.update(records.array(), 0, records.length());
        return crc.getValue();
    }

    long startTime() {
        return messages == 0 ? 0 : startTime;
    }

    long endTime() {
        return messages == 0 ? 0 : endTime;
    }

    /** The channels with messages in this chunk, in ascending id order. */
    int[] channels() {
        int[] ids = java.util.Arrays.copyOf(touched, touchedCount);
        java.util.Arrays.sort(ids);
        return ids;
    }

    RecordBuffer indexOf(int channel) {
        return index[channel];
    }

    void clear() {
        records.clear();
        for (int i = 0; i < touchedCount; i++) {
            index[touched[i]].clear();
        }
        touchedCount = 0;
        startTime = Long.MAX_VALUE;
        endTime = Long.MIN_VALUE;
        messages = 0;
    }
}

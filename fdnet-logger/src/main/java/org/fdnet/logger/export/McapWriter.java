package org.fdnet.logger.export;

import com.github.luben.zstd.Zstd;
import java.io.Closeable;
import java.io.IOException;
import java.io.OutputStream;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.zip.CRC32;

/**
 * Writes one MCAP file (the format Foxglove and PlotJuggler read: https://mcap.dev/spec) to a stream, front to
 * back, in bounded memory: schemas, channels and messages go into zstd-compressed chunks of about
 * {@code chunkBytes}, each followed by its message indexes; {@link #close} ends the data section and writes the
 * summary (schemas, channels, statistics, chunk, attachment and metadata indexes), the summary offsets and the
 * footer, with the CRCs the spec defines. Metadata and attachments are written between chunks.
 *
 * <pre>
 *   magic header │ [schema channel message…]zstd message-index… │ attachment metadata │ … │ data-end
 *                │ summary: schemas channels statistics chunk-indexes attachment-indexes metadata-indexes
 *                │ summary-offsets │ footer magic
 * </pre>
 *
 * Not thread-safe. Messages should be given in log-time order (each chunk's span and the indexes are right
 * either way, but readers that merge chunks read fastest when they do not overlap).
 */
public final class McapWriter implements Closeable {
    static final byte[] MAGIC = {(byte) 0x89, 'M', 'C', 'A', 'P', '0', '\r', '\n'};
    static final int OP_HEADER = 0x01;
    static final int OP_FOOTER = 0x02;
    static final int OP_SCHEMA = 0x03;
    static final int OP_CHANNEL = 0x04;
    static final int OP_MESSAGE = 0x05;
    static final int OP_CHUNK = 0x06;
    static final int OP_MESSAGE_INDEX = 0x07;
    static final int OP_CHUNK_INDEX = 0x08;
    static final int OP_ATTACHMENT = 0x09;
    static final int OP_ATTACHMENT_INDEX = 0x0A;
    static final int OP_STATISTICS = 0x0B;
    static final int OP_METADATA = 0x0C;
    static final int OP_METADATA_INDEX = 0x0D;
    static final int OP_SUMMARY_OFFSET = 0x0E;
    static final int OP_DATA_END = 0x0F;
    /** Channel ids are uint16 and 0 is kept free. */
    static final int MAX_CHANNELS = 65_535;
    private static final int ZSTD_LEVEL = 1;

    private final OutputStream out;
    private final int chunkBytes;
    private long position;
    private final CRC32 dataCrc = new CRC32();
    private final RecordBuffer scratch = new RecordBuffer(4096);
    private final McapChunk chunk = new McapChunk();

    private final List<byte[]> schemaRecords = new ArrayList<>();
    private final List<byte[]> channelRecords = new ArrayList<>();
    private final RecordBuffer chunkIndexes = new RecordBuffer(4096);
    private final RecordBuffer attachmentIndexes = new RecordBuffer(256);
    private final RecordBuffer metadataIndexes = new RecordBuffer(256);
    private long[] channelCounts = new long[16];
    private long[] channelSequence = new long[16];
    private long messageCount;
    private long startTime = Long.MAX_VALUE;
    private long endTime = Long.MIN_VALUE;
    private int chunkCount;
    private int attachmentCount;
    private int metadataCount;
    private boolean closed;
    private boolean dataEnded;

    /** Starts the file: magic and header ({@code profile} empty for none, {@code library} names the writer). */
    public McapWriter(OutputStream out, String profile, String library, int chunkBytes) throws IOException {
        if (chunkBytes < 1024) {
            throw new IllegalArgumentException("chunkBytes must be at least 1024, was " + chunkBytes);
        }
        this.out = out;
        this.chunkBytes = chunkBytes;
        write(MAGIC, 0, MAGIC.length);
        scratch.clear();
        scratch.string(profile).string(library);
        writeRecord(OP_HEADER, scratch);
    }

    /** Adds a schema (id 1, 2, …): written into the current chunk and kept for the summary. */
    public int schema(String name, String encoding, byte[] data) {
        int id = schemaRecords.size() + 1;
        if (id > MAX_CHANNELS) {
            throw new IllegalStateException("an MCAP file holds at most " + MAX_CHANNELS + " schemas");
        }
        scratch.clear();
        scratch.u16(id).string(name).string(encoding).u32(data.length).raw(data, 0, data.length);
        chunk.record(OP_SCHEMA, scratch);
        schemaRecords.add(recordBytes(OP_SCHEMA, scratch));
        return id;
    }

    /** Adds a channel (id 1, 2, …) on {@code topic} whose messages follow schema {@code schemaId}. */
    public int channel(int schemaId, String topic, String messageEncoding, Map<String, String> metadata) {
        int id = channelRecords.size() + 1;
        if (id > MAX_CHANNELS) {
            throw new IllegalStateException("an MCAP file holds at most " + MAX_CHANNELS + " channels; export fewer nodes");
        }
        scratch.clear();
        scratch.u16(id).u16(schemaId).string(topic).string(messageEncoding);
        stringMap(scratch, metadata);
        chunk.record(OP_CHANNEL, scratch);
        channelRecords.add(recordBytes(OP_CHANNEL, scratch));
        if (id >= channelCounts.length) {
            channelCounts = java.util.Arrays.copyOf(channelCounts, Math.max(id + 1, channelCounts.length * 2));
            channelSequence = java.util.Arrays.copyOf(channelSequence, channelCounts.length);
        }
        return id;
    }

    public int channelCount() {
        return channelRecords.size();
    }

    /** One message on {@code channel} at {@code logTimeNanos} (also its publish time), its body {@code data[off, off+n)}. */
    public void message(int channel, long logTimeNanos, byte[] data, int off, int n) throws IOException {
        if (channel < 1 || channel > channelRecords.size()) {
            throw new IllegalArgumentException("no channel " + channel);
        }
        chunk.message(channel, channelSequence[channel]++ & 0xFFFF_FFFFL, logTimeNanos, data, off, n);
        channelCounts[channel]++;
        messageCount++;
        startTime = Math.min(startTime, logTimeNanos);
        endTime = Math.max(endTime, logTimeNanos);
        if (chunk.uncompressedSize() >= chunkBytes) {
            flushChunk();
        }
    }

    public long messageCount() {
        return messageCount;
    }

    /** Bytes written so far (the whole file once closed). */
    public long position() {
        return position;
    }

    /** An attachment (a file carried along, e.g. the network's definition); ends the current chunk first. */
    public void attachment(String name, String mediaType, long logTimeNanos, byte[] data) throws IOException {
        flushChunk();
        scratch.clear();
        scratch.u64(logTimeNanos).u64(0).string(name).string(mediaType).u64(data.length).raw(data, 0, data.length);
        CRC32 crc = new CRC32();
        crc.update(scratch.array(), 0, scratch.length());
        scratch.u32(crc.getValue());
        long offset = position;
        writeRecord(OP_ATTACHMENT, scratch);
        attachmentIndexes.u8(OP_ATTACHMENT_INDEX);
        int lengthAt = attachmentIndexes.length();
        attachmentIndexes.u64(0).u64(offset).u64(position - offset).u64(logTimeNanos).u64(0).u64(data.length)
                .string(name).string(mediaType);
        attachmentIndexes.u64At(lengthAt, attachmentIndexes.length() - lengthAt - 8);
        attachmentCount++;
    }

    /** A named set of key-value pairs (e.g. the run's identity); ends the current chunk first. */
    public void metadata(String name, Map<String, String> values) throws IOException {
        flushChunk();
        scratch.clear();
        scratch.string(name);
        stringMap(scratch, values);
        long offset = position;
        writeRecord(OP_METADATA, scratch);
        metadataIndexes.u8(OP_METADATA_INDEX);
        int lengthAt = metadataIndexes.length();
        metadataIndexes.u64(0).u64(offset).u64(position - offset).string(name);
        metadataIndexes.u64At(lengthAt, metadataIndexes.length() - lengthAt - 8);
        metadataCount++;
    }

    /** Writes the last chunk, the data end, the summary and the footer, and closes the stream. */
    @Override
    public void close() throws IOException {
        if (closed) {
            return;
        }
        closed = true;
        try {
            flushChunk();
            dataEnded = true;
            scratch.clear();
            scratch.u32(dataCrc.getValue());
            writeRecord(OP_DATA_END, scratch);
            writeSummaryAndFooter();
            out.flush();
        } finally {
            out.close();
        }
    }

    private void flushChunk() throws IOException {
        if (chunk.isEmpty()) {
            return;
        }
        RecordBuffer records = chunk.records();
        byte[] compressed = Zstd.compress(java.util.Arrays.copyOf(records.array(), records.length()), ZSTD_LEVEL);
        long chunkStart = position;
        scratch.clear();
        scratch.u64(chunk.startTime()).u64(chunk.endTime()).u64(records.length()).u32(chunk.crc()).string("zstd")
                .u64(compressed.length).raw(compressed, 0, compressed.length);
        writeRecord(OP_CHUNK, scratch);
        long chunkLength = position - chunkStart;
        int[] channels = chunk.channels();
        long[] indexOffsets = new long[channels.length];
        long indexStart = position;
        for (int i = 0; i < channels.length; i++) {
            indexOffsets[i] = position;
            RecordBuffer entries = chunk.indexOf(channels[i]);
            scratch.clear();
            scratch.u16(channels[i]).u32(entries.length()).raw(entries);
            writeRecord(OP_MESSAGE_INDEX, scratch);
        }
        chunkIndexes.u8(OP_CHUNK_INDEX);
        int lengthAt = chunkIndexes.length();
        chunkIndexes.u64(0).u64(chunk.startTime()).u64(chunk.endTime()).u64(chunkStart).u64(chunkLength)
                .u32(channels.length * 10L);
        for (int i = 0; i < channels.length; i++) {
            chunkIndexes.u16(channels[i]).u64(indexOffsets[i]);
        }
        chunkIndexes.u64(position - indexStart).string("zstd").u64(compressed.length).u64(records.length());
        chunkIndexes.u64At(lengthAt, chunkIndexes.length() - lengthAt - 8);
        chunkCount++;
        chunk.clear();
    }

    private void writeSummaryAndFooter() throws IOException {
        long summaryStart = position;
        CRC32 summaryCrc = new CRC32();
        List<long[]> groups = new ArrayList<>(); // {opcode, start, length}
        groups.add(writeGroup(OP_SCHEMA, joined(schemaRecords), summaryCrc));
        groups.add(writeGroup(OP_CHANNEL, joined(channelRecords), summaryCrc));
        RecordBuffer stats = new RecordBuffer(256);
        stats.u8(OP_STATISTICS).u64(0);
        stats.u64(messageCount).u16(schemaRecords.size()).u32(channelRecords.size()).u32(attachmentCount)
                .u32(metadataCount).u32(chunkCount).u64(messageCount == 0 ? 0 : startTime)
                .u64(messageCount == 0 ? 0 : endTime);
        int mapAt = stats.length();
        stats.u32(0);
        for (int id = 1; id <= channelRecords.size(); id++) {
            stats.u16(id).u64(channelCounts[id]);
        }
        stats.u32At(mapAt, stats.length() - mapAt - 4);
        stats.u64At(1, stats.length() - 9);
        groups.add(writeGroup(OP_STATISTICS, stats, summaryCrc));
        groups.add(writeGroup(OP_CHUNK_INDEX, chunkIndexes, summaryCrc));
        groups.add(writeGroup(OP_ATTACHMENT_INDEX, attachmentIndexes, summaryCrc));
        groups.add(writeGroup(OP_METADATA_INDEX, metadataIndexes, summaryCrc));
        long offsetsStart = position;
        RecordBuffer offsets = new RecordBuffer(256);
        for (long[] g : groups) {
            if (g != null) {
                offsets.u8(OP_SUMMARY_OFFSET).u64(1 + 8 + 8).u8((int) g[0]).u64(g[1]).u64(g[2]);
            }
        }
        boolean anySummary = offsetsStart > summaryStart;
        offsets.u8(OP_FOOTER).u64(8 + 8 + 4).u64(anySummary ? summaryStart : 0).u64(offsets.length() > 0 ? offsetsStart : 0);
        // the footer's own two fields are in the summary CRC, the CRC field is not
        summaryCrc.update(offsets.array(), 0, offsets.length());
        offsets.u32(summaryCrc.getValue());
        offsets.raw(MAGIC, 0, MAGIC.length);
        write(offsets.array(), 0, offsets.length());
    }

    /** Writes one group of summary records; null when it is empty (no summary offset for it). */
    private long[] writeGroup(int opcode, RecordBuffer records, CRC32 crc) throws IOException {
        if (records.length() == 0) {
            return null;
        }
        long start = position;
        crc.update(records.array(), 0, records.length());
        write(records.array(), 0, records.length());
        return new long[] {opcode, start, records.length()};
    }

    private static RecordBuffer joined(List<byte[]> records) {
        RecordBuffer b = new RecordBuffer(1024);
        for (byte[] r : records) {
            b.raw(r, 0, r.length);
        }
        return b;
    }

    private static byte[] recordBytes(int opcode, RecordBuffer content) {
        RecordBuffer r = new RecordBuffer(content.length() + 9);
        r.u8(opcode).u64(content.length()).raw(content);
        return r.toByteArray();
    }

    private static void stringMap(RecordBuffer b, Map<String, String> map) {
        int at = b.length();
        b.u32(0);
        for (Map.Entry<String, String> e : new java.util.TreeMap<>(map).entrySet()) {
            b.string(e.getKey()).string(e.getValue());
        }
        b.u32At(at, b.length() - at - 4);
    }

    private final byte[] recordHead = new byte[9];

    private void writeRecord(int opcode, RecordBuffer content) throws IOException {
        recordHead[0] = (byte) opcode;
        long n = content.length();
        for (int i = 0; i < 8; i++) {
            recordHead[1 + i] = (byte) (n >>> (8 * i));
        }
        write(recordHead, 0, 9);
        write(content.array(), 0, content.length());
    }

    /** Every byte of the file passes here: its position, and the data section's CRC until the data end record. */
    private void write(byte[] b, int off, int n) throws IOException {
        out.write(b, off, n);
        position += n;
        if (!dataEnded) {
            dataCrc.update(b, off, n);
        }
    }
}

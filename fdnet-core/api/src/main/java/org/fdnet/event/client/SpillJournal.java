package org.fdnet.event.client;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.InputStream;
import java.io.OutputStream;
import java.io.UncheckedIOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.List;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.wire.EventCodec;
import org.fdnet.event.wire.Frame;
import org.fdnet.event.wire.FrameReader;
import org.fdnet.event.wire.FrameWriter;
import org.fdnet.event.wire.MessageType;
import org.fdnet.event.wire.Protocol;

/**
 * A bounded first-in first-out queue of events on disk, in segment files, for when the logger is slow or
 * away. Records are logger-protocol frames (one event each), so the journal needs no format of its own.
 * A segment is deleted as soon as it is read to its end; {@link #bytes()} counts the live segments and
 * {@link #hasRoomFor} refuses appends beyond the bound.
 *
 * <p>Not thread-safe: the owner ({@link LoggerClient}) calls it under its lock. It is a spill area, not
 * a durable log: it lives as long as the core that owns it and is deleted on {@link #close}.
 */
final class SpillJournal implements AutoCloseable {
    private static final long SEGMENT_BYTES = 64L << 20;

    private final Path directory;
    private final long maxBytes;
    private final FrameWriter frame = new FrameWriter();
    private final ArrayDeque<Segment> segments = new ArrayDeque<>();
    private OutputStream appender;
    private FrameReader reader;
    private InputStream readerStream;
    private long count;
    private long bytes;
    private int nextSegment;

    private record Segment(Path file, long[] records) {
    }

    SpillJournal(Path directory, long maxBytes) {
        this.directory = directory;
        this.maxBytes = maxBytes;
    }

    long count() {
        return count;
    }

    long bytes() {
        return bytes;
    }

    boolean isEmpty() {
        return count == 0;
    }

    /** Appends the event, or returns false (appending nothing) when it would pass the journal's bound. */
    boolean append(NetworkEvent event) {
        try {
            frame.begin(MessageType.EVENTS);
            EventCodec.write(frame, event);
            long size = frame.frameLength() + 4L;
            if (bytes + size > maxBytes) {
                return false;
            }
            if (segments.isEmpty() || segments.peekLast().records[1] >= SEGMENT_BYTES) {
                openSegment();
            }
            frame.writeTo(appender);
            Segment last = segments.peekLast();
            last.records[0]++;
            last.records[1] += size;
            bytes += size;
            count++;
            return true;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot append to the event journal in " + directory, e);
        }
    }

    /** Up to {@code max} of the oldest events, removed from the journal. */
    List<NetworkEvent> take(int max) {
        List<NetworkEvent> out = new ArrayList<>(Math.min(max, (int) Math.min(count, Integer.MAX_VALUE)));
        try {
            appender.flush();
            while (out.size() < max && count > 0) {
                Segment head = segments.peekFirst();
                if (reader == null) {
                    readerStream = new BufferedInputStream(Files.newInputStream(head.file), 1 << 16);
                    reader = new FrameReader(readerStream, Protocol.DEFAULT_MAX_FRAME_BYTES);
                }
                // records[2] counts what was read of this segment; records[0] what was appended.
                if (head.records[2] == head.records[0]) {
                    if (head == segments.peekLast()) {
                        break;
                    }
                    dropHead();
                    continue;
                }
                Frame f = reader.read();
                long size = f.remaining() + 5L;
                out.add(EventCodec.read(f));
                head.records[2]++;
                bytes -= size;
                count--;
            }
            Segment head = segments.peekFirst();
            if (head != null && head.records[2] == head.records[0] && head != segments.peekLast()) {
                dropHead();
            }
            return out;
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the event journal in " + directory, e);
        }
    }

    private void dropHead() throws IOException {
        Segment head = segments.pollFirst();
        readerStream.close();
        reader = null;
        Files.deleteIfExists(head.file);
    }

    private void openSegment() throws IOException {
        if (appender != null) {
            appender.close();
        }
        Files.createDirectories(directory);
        Path file = directory.resolve(String.format("segment-%06d.journal", nextSegment++));
        appender = new BufferedOutputStream(Files.newOutputStream(file), 1 << 16);
        segments.addLast(new Segment(file, new long[3]));
    }

    @Override
    public void close() {
        try {
            if (appender != null) {
                appender.close();
            }
            if (readerStream != null) {
                readerStream.close();
            }
            for (Segment s : segments) {
                Files.deleteIfExists(s.file);
            }
            segments.clear();
            Files.deleteIfExists(directory);
        } catch (IOException e) {
            throw new UncheckedIOException("cannot remove the event journal in " + directory, e);
        }
    }
}

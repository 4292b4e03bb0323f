package org.fdnet.event.client;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.ConcurrentHashMap;
import java.util.function.Consumer;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.wire.ErrorFrame;
import org.fdnet.event.wire.EventCodec;
import org.fdnet.event.wire.Frame;
import org.fdnet.event.wire.HistoryColumns;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.event.wire.LoggedRun;
import org.fdnet.event.wire.ProtocolException;

/**
 * What a viewer makes of the logger's frames after WELCOME: each answer goes to the open request it names
 * (an answer to a request no longer open is read and dropped), live events go to the monitor listener. A frame
 * that breaks the protocol fails with a {@link ProtocolException}; an ERROR frame with the logger's reason.
 *
 * <pre>
 *   HISTORY_CHUNK ─▶ request's events (or its HistoryColumns)   HISTORY_END ─▶ request done
 *   NODE_LIST, RUN_LIST ─▶ request's nodes or runs, done         MONITOR_EVENTS ─▶ listener
 * </pre>
 */
final class LoggerAnswers {
    /** One request waiting for its answer. */
    static final class Request {
        final List<Object> items = new ArrayList<>();
        /** Set for a history asked for as columns: the chunks are read into it, no object per event. */
        final HistoryColumns columns;
        final CompletableFuture<List<Object>> done = new CompletableFuture<>();

        Request(HistoryColumns columns) {
            this.columns = columns;
        }
    }

    private final Map<Integer, Request> open = new ConcurrentHashMap<>();
    private final Consumer<NetworkEvent> monitorListener;

    LoggerAnswers(Consumer<NetworkEvent> monitorListener) {
        this.monitorListener = monitorListener;
    }

    void open(int id, Request r) {
        open.put(id, r);
    }

    void close(int id) {
        open.remove(id);
    }

    /** The connection ended: every open request fails with {@code why}. */
    void failAll(IOException why) {
        open.values().forEach(r -> r.done.completeExceptionally(why));
    }

    void dispatch(Frame f) throws IOException {
        switch (f.type()) {
            case HISTORY_CHUNK -> {
                Request r = open.get(f.getInt());
                int n = f.getCount(EventCodec.MIN_EVENT_BYTES);
                if (r != null && r.columns != null) {
                    r.columns.appendAll(f, n);
                    return;
                }
                for (int i = 0; i < n; i++) {
                    NetworkEvent e = EventCodec.read(f);
                    if (r != null) {
                        r.items.add(e);
                    }
                }
            }
            case HISTORY_END -> {
                Request r = open.get(f.getInt());
                if (r != null) {
                    r.done.complete(r.items);
                }
            }
            case NODE_LIST -> list(f, 14, LoggedNode::read);
            case RUN_LIST -> list(f, LoggedRun.MIN_BYTES, LoggedRun::read);
            case MONITOR_EVENTS -> {
                int n = f.getCount(EventCodec.MIN_EVENT_BYTES);
                for (int i = 0; i < n; i++) {
                    monitorListener.accept(EventCodec.read(f));
                }
            }
            case ERROR -> {
                ErrorFrame err = ErrorFrame.read(f);
                throw new IOException("logger closed the viewer connection: " + err.message());
            }
            default -> throw new ProtocolException("unexpected " + f.type() + " from the logger");
        }
    }

    /** A list answer (nodes or runs): every item read, then the request it names is done. */
    private void list(Frame f, int minItemBytes, ItemReader reader) throws IOException {
        Request r = open.get(f.getInt());
        int n = f.getCount(minItemBytes);
        for (int i = 0; i < n; i++) {
            Object item = reader.read(f);
            if (r != null) {
                r.items.add(item);
            }
        }
        if (r != null) {
            r.done.complete(r.items);
        }
    }

    /** Reads one item of a list answer. */
    @FunctionalInterface
    private interface ItemReader {
        Object read(Frame f) throws IOException;
    }
}

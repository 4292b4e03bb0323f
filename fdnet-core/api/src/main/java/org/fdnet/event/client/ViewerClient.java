package org.fdnet.event.client;

import java.io.BufferedInputStream;
import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.net.Socket;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.ExecutionException;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.TimeoutException;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.Consumer;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.wire.ErrorFrame;
import org.fdnet.event.wire.Frame;
import org.fdnet.event.wire.FrameReader;
import org.fdnet.event.wire.FrameWriter;
import org.fdnet.event.wire.Hello;
import org.fdnet.event.wire.HistoryColumns;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.event.wire.LoggedRun;
import org.fdnet.event.wire.MessageType;
import org.fdnet.event.wire.Protocol;
import org.fdnet.event.wire.ProtocolException;
import org.fdnet.event.wire.ViewerRequest;
import org.fdnet.tls.TransportSecurity;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * A viewer's connection to the logger's sender server: node names, history of nodes over a time range,
 * and live monitoring. Requests may come from any thread; one reader thread dispatches the answers and
 * hands monitored events to the listener (keep the listener quick).
 *
 * <pre>
 *   nodes("Arm/")  ─LIST_NODES─▶ logger ─NODE_LIST─▶ List&lt;LoggedNode&gt;
 *   history(ids, from, to) ─HISTORY─▶ logger ─HISTORY_CHUNK*, HISTORY_END─▶ events in time order
 *   historyColumns(ids, from, to) ─HISTORY─▶ logger ─(the same answer, numbers read in place)─▶ HistoryColumns
 *   monitor(ids) ─MONITOR─▶ logger ─MONITOR_EVENTS (live)─▶ listener
 * </pre>
 */
public final class ViewerClient implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(ViewerClient.class);

    private final Socket socket;
    private final OutputStream out;
    private final FrameWriter writer = new FrameWriter();
    private final AtomicInteger requests = new AtomicInteger();
    private final LoggerAnswers answers;
    private final Thread reader;
    private volatile IOException failure;

    /**
     * Connects and greets the logger's sender server (over TLS when this process speaks it, see
     * {@link org.fdnet.tls.TransportSecurity}); waits at most 5 s for the connection.
     *
     * @param host            the sender server's address
     * @param port            its port
     * @param name            the viewer's name for the logger's client list
     * @param monitorListener gets every monitored event, on the reader thread; keep it quick
     * @throws IOException when the logger cannot be reached or refuses the viewer, saying why
     */
    public ViewerClient(String host, int port, String name, Consumer<NetworkEvent> monitorListener) throws IOException {
        this.answers = new LoggerAnswers(monitorListener);
        socket = TransportSecurity.connect(host, port, 5000);
        out = new BufferedOutputStream(socket.getOutputStream());
        FrameReader in = new FrameReader(new BufferedInputStream(socket.getInputStream()), Protocol.DEFAULT_MAX_FRAME_BYTES);
        synchronized (writer) {
            Hello.viewer(name).write(writer);
            writer.writeTo(out);
            out.flush();
        }
        Frame welcome = in.read();
        if (welcome == null || welcome.type() != MessageType.WELCOME) {
            String why = welcome != null && welcome.type() == MessageType.ERROR ? ErrorFrame.read(welcome).message()
                    : "no WELCOME";
            socket.close();
            throw new IOException("logger at " + host + ":" + port + " refused the viewer: " + why);
        }
        reader = new Thread(() -> readLoop(in), "fdnet-viewer-client");
        reader.setDaemon(true);
        reader.setPriority(Thread.MAX_PRIORITY); // answers are waited for; on Linux only with -XX:ThreadPriorityPolicy=1

        reader.start();
    }

    /**
     * Nodes whose name matches: {@code ""} all, {@code Node} any module, {@code Module/Node} exactly.
     *
     * @param filter the name filter
     * @return the matching nodes of every stream the logger holds
     * @throws IOException when the connection is lost, the logger refuses, or it does not answer within 60 s
     */
    public List<LoggedNode> nodes(String filter) throws IOException {
        int id = requests.incrementAndGet();
        List<Object> items = call(id, new LoggerAnswers.Request(null), ViewerRequest.listNodes(id, filter)::write);
        List<LoggedNode> nodes = new ArrayList<>(items.size());
        items.forEach(o -> nodes.add((LoggedNode) o));
        return nodes;
    }

    /**
     * Every stream of events the logger holds, with the network run each belongs to.
     *
     * @return the streams, from the logger's database (none while it is unavailable)
     * @throws IOException when the connection is lost, the logger refuses, or it does not answer within 60 s
     */
    public List<LoggedRun> runs() throws IOException {
        int id = requests.incrementAndGet();
        List<Object> items = call(id, new LoggerAnswers.Request(null), ViewerRequest.listRuns(id)::write);
        List<LoggedRun> runs = new ArrayList<>(items.size());
        items.forEach(o -> runs.add((LoggedRun) o));
        return runs;
    }

    /**
     * Every event of the nodes with {@code from <= time <= to}, in time order (cache and database merged).
     *
     * @param sourceIds the logger's node ids ({@link LoggedNode#sourceId()}), at most
     *                  {@link org.fdnet.event.wire.ViewerRequest#MAX_NODES}
     * @param from      the first time, µs since the epoch, inclusive
     * @param to        the last time, µs since the epoch, inclusive
     * @return the events, with the logger's source ids
     * @throws IOException when the connection is lost, the logger refuses, or it does not answer within 60 s
     */
    public List<NetworkEvent> history(int[] sourceIds, long from, long to) throws IOException {
        List<Object> items = askHistory(MessageType.HISTORY, sourceIds, from, to, new LoggerAnswers.Request(null));
        List<NetworkEvent> events = new ArrayList<>(items.size());
        items.forEach(o -> events.add((NetworkEvent) o));
        return events;
    }

    /**
     * The same answer as {@link #history}, as columns: times, source ids and numeric values without an object
     * or a String per event (numbers are 8 bytes on the wire, read in place) — the path for plotting.
     *
     * @param sourceIds the logger's node ids, as for {@link #history}
     * @param from      the first time, µs since the epoch, inclusive
     * @param to        the last time, µs since the epoch, inclusive
     * @return the events as columns, in time order
     * @throws IOException when the connection is lost, the logger refuses, or it does not answer within 60 s
     */
    public HistoryColumns historyColumns(int[] sourceIds, long from, long to) throws IOException {
        LoggerAnswers.Request r = new LoggerAnswers.Request(new HistoryColumns());
        askHistory(MessageType.HISTORY, sourceIds, from, to, r);
        return r.columns;
    }

    private List<Object> askHistory(MessageType type, int[] sourceIds, long from, long to, LoggerAnswers.Request r) throws IOException {
        int id = requests.incrementAndGet();
        return call(id, r, ViewerRequest.history(type, id, sourceIds, from, to)::write);
    }

    /**
     * Starts streaming the nodes' new events to the listener.
     *
     * @param sourceIds the logger's node ids
     * @throws IOException when the connection is lost or the request cannot be sent
     */
    public void monitor(int... sourceIds) throws IOException {
        send(ViewerRequest.monitor(MessageType.MONITOR, sourceIds)::write);
    }

    /**
     * Stops streaming the nodes (none given: all).
     *
     * @param sourceIds the logger's node ids; none for every monitored node
     * @throws IOException when the connection is lost or the request cannot be sent
     */
    public void unmonitor(int... sourceIds) throws IOException {
        send(ViewerRequest.monitor(MessageType.UNMONITOR, sourceIds)::write);
    }

    private interface FrameBuilder {
        void build(FrameWriter w);
    }

    private void send(FrameBuilder b) throws IOException {
        if (failure != null) {
            throw new IOException("viewer connection lost", failure);
        }
        synchronized (writer) {
            b.build(writer);
            writer.writeTo(out);
            out.flush();
        }
    }

    private List<Object> call(int id, LoggerAnswers.Request r, FrameBuilder b) throws IOException {
        answers.open(id, r);
        send(b);
        try {
            return r.done.get(60, TimeUnit.SECONDS);
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            throw new IOException("interrupted while waiting for the logger", e);
        } catch (ExecutionException e) {
            throw new IOException("logger request failed: " + e.getCause().getMessage(), e.getCause());
        } catch (TimeoutException e) {
            throw new IOException("logger did not answer within 60 s", e);
        } finally {
            answers.close(id);
        }
    }

    private void readLoop(FrameReader in) {
        ResponsiveThreads.raiseCurrent("a viewer's reader thread");
        try {
            Frame f;
            while ((f = in.read()) != null) {
                answers.dispatch(f);
            }
            failure = new IOException("logger closed the connection");
        } catch (IOException e) {
            failure = e;
        } finally {
            IOException why = failure != null ? failure : new IOException("connection closed");
            answers.failAll(why);
        }
    }

    @Override
    public void close() {
        try {
            socket.close();
            reader.join(2000);
        } catch (IOException e) {
            LOG.debug("closing viewer socket: {}", e.getMessage());
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
        }
    }
}

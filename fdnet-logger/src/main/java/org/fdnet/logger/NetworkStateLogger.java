package org.fdnet.logger;

import java.io.IOException;
import java.sql.SQLException;
import java.util.List;
import org.fdnet.logger.cache.CacheLimits;
import org.fdnet.logger.cache.CacheStatus;
import org.fdnet.logger.cache.EventCache;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.config.LoggerSetting;
import org.fdnet.logger.server.Servers;
import org.fdnet.logger.server.TcpServer;
import org.fdnet.logger.server.ViewerService;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.logger.store.EmbeddedDatabase;
import org.fdnet.logger.store.EventStore;
import org.fdnet.logger.store.QueryPriority;
import org.fdnet.logger.store.SourceDirectory;
import org.fdnet.logger.writer.BatchWriter;
import org.fdnet.logger.writer.WriterSettings;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * The network state logger (thesis, chapter 4): assembles database, cache, writer and the two servers from
 * one sealed configuration, and takes them down in the order that loses nothing — receivers first, then
 * the writer drains the cache, then viewers and the database.
 *
 * <p>Hazard: {@link #stop} with the database down waits at most the drain timeout; what is left unwritten
 * was never acknowledged, so the cores still hold it and send it to the next logger.
 */
public final class NetworkStateLogger implements AutoCloseable {
    private static final Logger LOG = LoggerFactory.getLogger(NetworkStateLogger.class);
    private static final long DRAIN_TIMEOUT_MILLIS = 60_000;
    /**
     * How long a viewer's history waits for the flush it asked for. Short on purpose: the answer reads the
     * cache before the database and events leave the cache only after their commit, so it is complete
     * without the flush; waiting for a large backlog (a burst) would only make the viewer slow.
     */
    private static final long VIEWER_FLUSH_WAIT_MILLIS = 200;

    private final LoggerConfig config;
    private EmbeddedDatabase embedded;
    private EventStore store;
    private EventCache cache;
    private SourceDirectory directory;
    private BatchWriter writer;
    private QueryPriority queries;
    private Thread writerThread;
    private TcpServer receiver;
    private TcpServer sender;
    private volatile boolean running;
    private final Throughput in = new Throughput();
    private final Throughput out = new Throughput();

    public NetworkStateLogger(LoggerConfig config) {
        this.config = config;
    }

    public LoggerConfig config() {
        return config;
    }

    /** Starts everything; on failure, what was started is stopped again and the cause rethrown. */
    public synchronized void start() throws IOException, SQLException {
        if (running) {
            return;
        }
        config.seal();
        try {
            DatabaseTarget target;
            if (config.embeddedDatabase()) {
                embedded = EmbeddedDatabase.start(config.embeddedDirectory(), 0, config.embeddedFsync());
                target = embedded.target();
            } else {
                target = new DatabaseTarget(config.jdbcUrl(), config.databaseUser(), config.databasePassword());
            }
            queries = new QueryPriority(config.queryPauseMillis());
            store = new EventStore(target, queries, config.backendNiceness());
            store.createSchema();
            directory = new SourceDirectory(store);
            directory.load();
            cache = new EventCache(new CacheLimits(config.cacheCapacityBytes(), config.networkEventBytes(),
                    config.commandEventBytes(), config.criticalPercent(), config.normalPercent()));
            writer = new BatchWriter(WriterSettings.of(config), cache, store, directory, this::giveUp);
            writerThread = new Thread(writer, "fdnet-logger-writer");
            writerThread.start();
            ViewerService viewers = new ViewerService(cache, store, directory, writer, VIEWER_FLUSH_WAIT_MILLIS, queries);
            receiver = Servers.receiver(config, cache, directory, queries);
            sender = Servers.sender(config, viewers);
            running = true;
            LOG.info("logger started: cores on {}:{}, viewers on {}:{}, database {}", config.receiverAddress(),
                    receiver.port(), config.senderAddress(), sender.port(), target);
        } catch (IOException | SQLException | RuntimeException e) {
            shutdown();
            throw e;
        }
    }

    private void giveUp() {
        Thread t = new Thread(this::stop, "fdnet-logger-stop");
        t.start();
    }

    /**
     * Changes a setting while the logger runs: a {@link LoggerSetting#live() live} one is checked and applied at
     * once; any other is refused (it takes effect at the next start).
     *
     * @throws IllegalArgumentException naming the setting and why its value is refused
     * @throws IllegalStateException for a setting that is not live
     */
    public void applyLive(LoggerSetting setting, String value) {
        if (!setting.live()) {
            throw new IllegalStateException(setting.key() + " takes effect at the next start");
        }
        config.setLive(setting, value);
        BatchWriter w = writer;
        if (w != null) {
            w.retune(WriterSettings.of(config));
        }
    }

    public int receiverPort() {
        return receiver.port();
    }

    public int senderPort() {
        return sender.port();
    }

    public boolean running() {
        return running;
    }

    public EventCache cache() {
        return cache;
    }

    /** After the writer reported the database down (its attempts used up): try the database again. */
    public void retryDatabase() {
        BatchWriter w = writer;
        if (w != null) {
            w.retryDatabase();
        }
    }

    /** How viewer queries take precedence over the writer and receivers (see {@link QueryPriority}). */
    public QueryPriority queries() {
        return queries;
    }

    public BatchWriter writer() {
        return writer;
    }

    public SourceDirectory directory() {
        return directory;
    }

    public EventStore store() {
        return store;
    }

    public LoggerStatus status() {
        if (!running) {
            return new LoggerStatus(false, null, 0, 0, "-", List.of(), List.of(), 0, 0, 0);
        }
        CacheStatus c = cache.status();
        return new LoggerStatus(true, c, in.rate(c.received()), out.rate(c.committed()), writer.databaseState(),
                receiver.factory().clients(), sender.factory().clients(), writer.lastBatchRows(), writer.maxBatchRows(),
                writer.connections());
    }

    /** Stops the receivers, lets the writer drain (bounded), then stops the rest. */
    public synchronized void stop() {
        if (!running) {
            return;
        }
        running = false;
        shutdown();
    }

    private void shutdown() {
        if (receiver != null) {
            receiver.close();
        }
        if (writer != null) {
            writer.stop(true);
            try {
                writerThread.join(DRAIN_TIMEOUT_MILLIS);
                if (writerThread.isAlive()) {
                    LOG.error("writer could not drain within {} ms; {} unwritten events stay with their cores",
                            DRAIN_TIMEOUT_MILLIS, cache.unwrittenCount());
                    writer.stop(false);
                    writerThread.join(10_000);
                }
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        }
        if (sender != null) {
            sender.close();
        }
        if (store != null) {
            store.close();
        }
        if (embedded != null) {
            try {
                embedded.close();
            } catch (IOException e) {
                LOG.warn("stopping embedded PostgreSQL: {}", e.getMessage());
            }
        }
        LOG.info("logger stopped");
    }

    @Override
    public void close() {
        stop();
    }
}

package org.fdnet.logger.bench;

import java.nio.file.Files;
import java.nio.file.Path;
import java.sql.Connection;
import java.sql.DriverManager;
import java.sql.ResultSet;
import java.sql.SQLException;
import java.sql.Statement;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;
import org.HdrHistogram.Histogram;
import org.fdnet.event.client.ViewerClient;
import org.fdnet.logger.NetworkStateLogger;
import org.fdnet.logger.config.LoggerConfig;
import org.fdnet.logger.store.DatabaseTarget;
import org.fdnet.tls.KeyMaker;
import org.fdnet.tls.TlsIdentity;
import org.fdnet.tls.TransportSecurity;

/**
 * {@code bench logger --tls}, phase [5]: what mutual TLS costs the logger's two ports. The same measurement twice in
 * one run, plain then TLS, each into a fresh logger on the same database: a producer process at full speed for
 * {@code seconds} (events per second, first to last commit) and 2,000 viewer requests after 1,000 to warm up (a
 * node list: one round trip each) on the viewer port.
 */
final class LoggerTlsCost {
    private static final int QUERIES = 2_000;
    private static final int WARM_UP = 1_000;

    private final LoggerConfig config;
    private final DatabaseTarget target;
    private final int seconds;
    private final int nodes;

    LoggerTlsCost(LoggerConfig config, DatabaseTarget target, int seconds, int nodes) {
        this.config = config;
        this.target = target;
        this.seconds = seconds;
        this.nodes = nodes;
    }

    /** One side's figures. */
    private record Figures(double eventsPerSecond, Histogram query) {
    }

    void run() throws Exception {
        System.out.printf("%n[5] TLS cost: a producer at full speed for %d s and %d viewer requests, plain then mutual"
                + " TLS (a fresh logger each, same database) ...%n", seconds, QUERIES);
        Figures plain = measure("plain", null);
        KeyMaker keys = new KeyMaker(Files.createTempDirectory("fdnet-bench-keys-"));
        Figures secure;
        try {
            keys.make(List.of("bench-logger", "bench-producer"));
            TransportSecurity.use(TlsIdentity.load(keys.store("bench-logger")));
            secure = measure("tls", keys.store("bench-producer"));
        } finally {
            TransportSecurity.off();
            keys.deleteAll();
        }
        System.out.printf("  %-40s %12s %12s %9s%n", "", "plain", "TLS", "TLS/plain");
        row("producer -> logger, events/s", plain.eventsPerSecond(), secure.eventsPerSecond());
        row("viewer request p50 (us)", plain.query().getValueAtPercentile(50) / 1e3,
                secure.query().getValueAtPercentile(50) / 1e3);
        row("viewer request p99 (us)", plain.query().getValueAtPercentile(99) / 1e3,
                secure.query().getValueAtPercentile(99) / 1e3);
    }

    private Figures measure(String module, Path producerStore) throws Exception {
        try (NetworkStateLogger logger = new NetworkStateLogger(config)) {
            logger.start();
            AtomicLong first = new AtomicLong();
            AtomicLong last = new AtomicLong();
            long before = count();
            logger.writer().observe(b -> {
                long now = System.nanoTime();
                first.compareAndSet(0, now);
                last.set(now);
            });
            try (ProducerProcess producer = new ProducerProcess(logger.receiverPort(), Long.MAX_VALUE, seconds, nodes, 0,
                    "tlscost-" + module, false, 0, producerStore)) {
                producer.outcome();
            }
            logger.writer().observe(null);
            double rate = (count() - before) / ((last.get() - first.get()) / 1e9);
            Histogram query = new Histogram(3);
            try (ViewerClient viewer = new ViewerClient("127.0.0.1", logger.senderPort(), "bench-tls-viewer", e -> { })) {
                for (int i = 0; i < QUERIES + WARM_UP; i++) {
                    long t = System.nanoTime();
                    viewer.nodes("tlscost-" + module + "/Data1");
                    if (i >= WARM_UP) {
                        query.recordValue(System.nanoTime() - t);
                    }
                }
            }
            System.out.printf("  %-5s %,.0f events/s; viewer request p50 %.0f us, p99 %.0f us%n", module, rate,
                    query.getValueAtPercentile(50) / 1e3, query.getValueAtPercentile(99) / 1e3);
            return new Figures(rate, query);
        }
    }

    private long count() throws SQLException {
        try (Connection c = DriverManager.getConnection(target.url(), target.user(), target.password());
             Statement s = c.createStatement(); ResultSet rs = s.executeQuery("SELECT count(*) FROM datavalue_log")) {
            rs.next();
            return rs.getLong(1);
        }
    }

    private static void row(String label, double plain, double secure) {
        System.out.printf("  %-40s %,12.1f %,12.1f %9.2f%n", label, plain, secure, secure / plain);
    }
}

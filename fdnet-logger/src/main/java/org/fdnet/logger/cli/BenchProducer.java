package org.fdnet.logger.cli;

import java.time.Duration;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.EventClock;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.ValueType;
import org.fdnet.event.client.ClientStatus;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * The benchmark's producer process: a core's real logger client sending Data values of {@code nodes}
 * nodes round-robin as fast as it can, for {@code events} events or {@code seconds} seconds, then waiting
 * until the logger has committed everything. Prints {@code accepted N lost L acked A}.
 * Usage: {@code BenchProducer HOST PORT EVENTS SECONDS NODES}
 */
public final class BenchProducer {
    private BenchProducer() {
    }

    public static void main(String[] args) throws InterruptedException {
        String host = args[0];
        int port = Integer.parseInt(args[1]);
        long events = Long.parseLong(args[2]);
        long seconds = Long.parseLong(args[3]);
        int nodes = Integer.parseInt(args[4]);
        LoggerClientSettings settings = LoggerClientSettings.defaults(host, port, "bench-producer")
                .withFlushTimeout(Duration.ofMinutes(10));
        EventClock clock = new EventClock();
        try (LoggerClient client = new LoggerClient(settings)) {
            for (int n = 0; n < nodes; n++) {
                client.accept(new NodeNamedEvent(n, clock.next(), NodeKind.DATA, new NodeRef("bench", "Data" + n)));
            }
            long deadline = System.nanoTime() + seconds * 1_000_000_000L;
            long sent = 0;
            int window = settings.memoryEvents() * 9 / 10;
            while (sent < events && System.nanoTime() < deadline) {
                // As fast as the logger takes them, but no faster: a core that outruns its logger spills to the
                // journal, and this benchmark measures the logger, not the producer's disk.
                while (client.status().inMemory() >= window) {
                    Thread.sleep(1); // not a spin: the producer must not take the database's CPU
                }
                for (int i = 0; i < 1024 && sent < events; i++) {
                    int node = (int) (sent % nodes);
                    client.accept(new DataValueEvent(node, clock.next(), ValueType.DOUBLE, Double.toString(sent * 0.001)));
                    sent++;
                }
            }
            System.out.println("produced " + sent);
            System.out.flush();
            client.flush();
            ClientStatus s = client.status();
            System.out.println("accepted " + s.accepted() + " lost " + s.lost() + " acked " + s.acked());
        }
    }
}

package org.fdnet.logger.bench;

import java.nio.file.Path;
import org.fdnet.tls.TlsIdentity;
import org.fdnet.tls.TransportSecurity;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.time.Duration;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.EventClock;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.TypedValue;
import org.fdnet.event.client.ClientStatus;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;

/**
 * The benchmark's producer process: a core's real logger client naming {@code nodes} nodes of module
 * {@code module} and sending their Data values round-robin — as fast as the logger takes them
 * ({@code rate} 0) or at {@code rate} events per second — for {@code events} events or {@code seconds}
 * seconds, then waiting until the logger has committed everything. With {@code go}, it prints
 * {@code named} once its names are committed and waits for a line on its input before sending values.
 * {@code memoryEvents} (0: the client's default) is the client's in-memory window: the burst gives it room
 * for all its events, so that the logger's receiver and cache — not the client — decide the pace.
 * Prints {@code accepted N lost L acked A}.
 * Usage: {@code BenchProducer HOST PORT EVENTS SECONDS NODES RATE MODULE go|now MEMORY_EVENTS [TLS_STORE]}
 */
public final class BenchProducer {
    private BenchProducer() {
    }

    public static void main(String[] args) throws InterruptedException, IOException {
        String host = args[0];
        int port = Integer.parseInt(args[1]);
        long events = Long.parseLong(args[2]);
        long seconds = Long.parseLong(args[3]);
        int nodes = Integer.parseInt(args[4]);
        long rate = Long.parseLong(args[5]);
        String module = args[6];
        boolean waitForGo = args[7].equals("go");
        int memoryEvents = Integer.parseInt(args[8]);
        if (args.length > 9) {
            TransportSecurity.use(TlsIdentity.load(Path.of(args[9])));
        }
        LoggerClientSettings settings = LoggerClientSettings.defaults(host, port, "bench-" + module)
                .withFlushTimeout(Duration.ofMinutes(10));
        if (memoryEvents > 0) {
            settings = settings.withMemoryEvents(memoryEvents);
        }
        EventClock clock = new EventClock();
        try (LoggerClient client = new LoggerClient(settings)) {
            for (int n = 0; n < nodes; n++) {
                client.accept(new NodeNamedEvent(n, clock.next(), NodeKind.DATA, new NodeRef(module, "Data" + n)));
            }
            if (waitForGo) {
                client.flush();
                System.out.println("named");
                System.out.flush();
                new BufferedReader(new InputStreamReader(System.in, StandardCharsets.UTF_8)).readLine();
            }
            long start = System.nanoTime();
            long deadline = start + seconds * 1_000_000_000L;
            long sent = 0;
            int window = settings.memoryEvents() * 9 / 10;
            while (sent < events && System.nanoTime() < deadline) {
                // As fast as the logger takes them, but no faster: a core that outruns its logger spills to the
                // journal, and this benchmark measures the logger, not the producer's disk.
                while (client.status().inMemory() >= window) {
                    Thread.sleep(1); // not a spin: the producer must not take the database's CPU
                }
                long due = rate <= 0 ? sent + 1024 : (System.nanoTime() - start) * rate / 1_000_000_000L;
                if (due <= sent) {
                    Thread.sleep(1);
                    continue;
                }
                for (long i = sent; i < due && sent < events; i++) {
                    int node = (int) (sent % nodes);
                    client.accept(new DataValueEvent(node, clock.next(), TypedValue.of(sent * 0.001)));
                    sent++;
                }
            }
            System.out.println("produced " + sent + " in " + (System.nanoTime() - start) / 1_000_000 + " ms");
            System.out.flush();
            client.flush();
            ClientStatus s = client.status();
            System.out.println("accepted " + s.accepted() + " lost " + s.lost() + " acked " + s.acked());
        }
    }
}

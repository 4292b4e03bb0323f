package org.fdnet.apart;

import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentHashMap;
import java.util.concurrent.atomic.AtomicLong;
import java.util.stream.Collectors;
import org.fdnet.event.client.ViewerClient;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.tls.TlsIdentity;
import org.fdnet.tls.TransportSecurity;

/**
 * A viewer on a host of the rig: connects to the logger's viewer port with its certificate (the viewer's own client,
 * {@link ViewerClient}), waits until the logger knows the Datas named, watches them live for a few seconds and reads
 * their history. Arguments: {@code VIEWER.p12 ADDRESS:PORT SECONDS DATA...}; prints {@code viewer live DATA N} and
 * {@code viewer history DATA N} per Data.
 */
public final class ViewerProbe {
    private ViewerProbe() {
    }

    public static void main(String[] args) throws Exception {
        TransportSecurity.use(TlsIdentity.load(Path.of(args[0])));
        String host = args[1].substring(0, args[1].lastIndexOf(':'));
        int port = Integer.parseInt(args[1].substring(args[1].lastIndexOf(':') + 1));
        long seconds = Long.parseLong(args[2]);
        List<String> datas = List.of(args).subList(3, args.length);
        Map<Integer, AtomicLong> live = new ConcurrentHashMap<>();
        try (ViewerClient viewer = new ViewerClient(host, port, "apart-viewer",
                e -> live.computeIfAbsent(e.sourceId(), id -> new AtomicLong()).incrementAndGet())) {
            Map<String, LoggedNode> nodes = Map.of();
            long deadline = System.currentTimeMillis() + 60_000;
            while (nodes.size() < datas.size() && System.currentTimeMillis() < deadline) {
                nodes = viewer.nodes("").stream().filter(n -> datas.contains(n.name().node()))
                        .collect(Collectors.toMap(n -> n.name().node(), n -> n, (a, b) -> b));
                Thread.sleep(200);
            }
            int[] ids = nodes.values().stream().mapToInt(LoggedNode::sourceId).toArray();
            viewer.monitor(ids);
            Thread.sleep(seconds * 1000);
            for (String data : datas) {
                LoggedNode node = nodes.get(data);
                long liveCount = node == null ? 0 : live.getOrDefault(node.sourceId(), new AtomicLong()).get();
                long history = node == null ? 0
                        : viewer.history(new int[] {node.sourceId()}, 0, Long.MAX_VALUE).size();
                System.out.println("viewer live " + data + " " + liveCount);
                System.out.println("viewer history " + data + " " + history);
            }
        }
        System.out.flush();
    }
}

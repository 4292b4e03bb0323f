package org.fdnet.viewer;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.RunIdentity;
import org.fdnet.event.ValueType;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.logger.InProcessLogger;
import org.fdnet.viewer.data.PlotData;
import org.fdnet.viewer.source.LoggerConnection;
import org.fdnet.viewer.source.RunInfo;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A run recorded by three hosts whose clocks disagree is one run in the viewer: listed once with its network and
 * hosts, its Datas by host, and every host's values on the coordinator's time axis (each host's clock offset,
 * recorded with its stream, taken off).
 */
@Timeout(value = 120, unit = TimeUnit.SECONDS)
class WholeRunViewTest {
    private static final Map<String, Long> CLOCK_AHEAD = Map.of("flyer", 0L, "crawler", 5_000_000L,
            "operator", -2_000_000L);
    private static final Map<String, String> DATA = Map.of("flyer", "Map", "crawler", "Heading", "operator", "Shown");

    @Test
    void shouldShowEveryHostsDatasAsOneRunOnOneTimeAxis() throws Exception {
        long base = System.currentTimeMillis() * 1000 - 30_000_000;
        RunIdentity run = RunIdentity.start("two-robots", "<cnet name=\"two-robots\"/>",
                List.of("flyer", "crawler", "operator"));
        try (InProcessLogger logger = InProcessLogger.throwaway()) {
            for (String host : run.hosts()) {
                long ahead = CLOCK_AHEAD.get(host);
                LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(),
                        "fdnet host " + host), run, host, ahead);
                client.accept(new NodeNamedEvent(1, base + ahead, NodeKind.DATA, new NodeRef("main", DATA.get(host))));
                for (int second = 1; second <= 3; second++) { // the same coordinator times, on each host's clock
                    client.accept(new DataValueEvent(1, base + second * 1_000_000L + ahead, ValueType.LONG,
                            Integer.toString(second)));
                }
                assertThat(client.flush(30_000)).isTrue();
                client.close();
            }
            try (LoggerConnection viewer = new LoggerConnection(logger.viewerAddress(), new PlotData())) {
                List<RunInfo> runs = viewer.runs();
                assertThat(runs).hasSize(1);
                RunInfo whole = runs.get(0);
                assertThat(whole.toString()).startsWith("two-robots, 3 hosts, started ");
                assertThat(whole.nodesByHost()).extracting(n -> whole.hostOf(n) + " " + LoggerConnection.label(n))
                        .containsExactly("crawler main/Heading", "flyer main/Map", "operator main/Shown");

                List<Long> times = new ArrayList<>();
                for (NetworkEvent e : viewer.history(whole.sourceIds(), 0, Long.MAX_VALUE)) {
                    if (e instanceof DataValueEvent) {
                        times.add(e.time() - base);
                    }
                }
                assertThat(times).containsExactly(1_000_000L, 1_000_000L, 1_000_000L, 2_000_000L, 2_000_000L,
                        2_000_000L, 3_000_000L, 3_000_000L, 3_000_000L);

                PlotData plot = new PlotData();
                for (LoggedNode n : whole.nodes()) {
                    plot.track(n.sourceId(), LoggerConnection.label(n), "");
                }
                viewer.loadHistory(whole.sourceIds(), 0, Long.MAX_VALUE, plot);
                for (LoggedNode n : whole.nodes()) {
                    long[] plotted = plot.seriesOf(n.sourceId()).get(0).range(Long.MIN_VALUE, Long.MAX_VALUE).times();
                    assertThat(plotted).as(LoggerConnection.label(n))
                            .containsExactly(base + 1_000_000L, base + 2_000_000L, base + 3_000_000L);
                }
            }
        }
    }
}

package org.fdnet.viewer;

import static org.assertj.core.api.Assertions.assertThat;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.TimeUnit;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.NetworkEvent;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.ValueType;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.event.wire.LoggedNode;
import org.fdnet.logger.InProcessLogger;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.netinfo.xml.NetworkRepository;
import org.fdnet.runtime.engine.RuntimeNetwork;
import org.fdnet.runtime.engine.RuntimeOptions;
import org.fdnet.viewer.data.PlotData;
import org.fdnet.viewer.data.SampleDecoder;
import org.fdnet.viewer.data.Series;
import org.fdnet.viewer.source.LoggerConnection;
import org.fdnet.viewer.source.Replay;
import org.fdnet.viewer.source.ReplayLoader;
import org.fdnet.viewer.source.RunInfo;
import org.junit.jupiter.api.AfterAll;
import org.junit.jupiter.api.BeforeAll;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/** The viewer against a real logger on embedded PostgreSQL: live values of a running network, and replay. */
@Timeout(value = 180, unit = TimeUnit.SECONDS)
class ViewerEndToEndTest {
    private static InProcessLogger logger;

    @BeforeAll
    static void startLogger() throws Exception {
        logger = InProcessLogger.throwaway();
    }

    @AfterAll
    static void stopLogger() throws Exception {
        if (logger != null) {
            logger.close();
        }
    }

    @Test
    void shouldReceiveExactlyTheLoggedValuesOfTheMonitoredNodesOfARunningNetwork() throws Exception {
        List<NetworkEvent> monitored = new CopyOnWriteArrayList<>();
        PlotData live = new PlotData();
        try (LoggerConnection viewer = new LoggerConnection(logger.viewerAddress(), live, monitored::add)) {
            LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(), "arms"));
            RuntimeNetwork network = RuntimeNetwork.start(NetworkRepository.load(Path.of("../networks/arms.fdn")),
                    RuntimeOptions.defaults().sink(client));
            List<LoggedNode> watched;
            try {
                watched = newestRunNodesOnceNamed(viewer, client, "Clock");
                viewer.watchNodes(watched);
                Thread.sleep(2000); // the network writes Clock every 20 ms meanwhile
            } finally {
                network.close();
                assertThat(client.flush(60_000)).as("every event committed").isTrue();
                client.close();
            }
            int[] ids = watched.stream().mapToInt(LoggedNode::sourceId).toArray();
            waitUntilStill(monitored);
            Map<Integer, List<NetworkEvent>> got = bySource(monitored);
            assertThat(got.get(viewer.resolve(org.fdnet.viewer.data.NodeSelection.parse("Clock")).sourceId()))
                    .as("Clock's monitored values").hasSizeGreaterThan(20);
            for (int id : ids) {
                List<NetworkEvent> mine = got.getOrDefault(id, List.of());
                if (mine.isEmpty()) {
                    continue;
                }
                List<NetworkEvent> logged = new ArrayList<>();
                for (NetworkEvent e : viewer.history(new int[] {id}, mine.get(0).time(), Long.MAX_VALUE)) {
                    if (e instanceof DataValueEvent) {
                        logged.add(e);
                    }
                }
                assertThat(mine).as("values of source %d, live vs logged", id).containsExactlyElementsOf(logged);
                PlotData history = new PlotData();
                history.track(id, "history", "");
                assertThat(viewer.loadHistory(new int[] {id}, mine.get(0).time(), Long.MAX_VALUE, history))
                        .as("history loaded into a plot").isEqualTo(logged.size());
                List<Series> series = live.seriesOf(id);
                double[] first = SampleDecoder.numbers((DataValueEvent) mine.get(0));
                if (first.length > 0) {
                    Series.Samples plotted = series.get(0).range(Long.MIN_VALUE, Long.MAX_VALUE);
                    assertThat(plotted.size()).as("plotted samples of source %d", id).isEqualTo(mine.size());
                    for (int i = 0; i < mine.size(); i++) {
                        assertThat(plotted.times()[i]).isEqualTo(mine.get(i).time());
                        assertThat(plotted.values()[i]).isEqualTo(SampleDecoder.numbers((DataValueEvent) mine.get(i))[0]);
                    }
                }
            }
        }
    }

    @Test
    void shouldReplayAPastRunsValuesInOrderAtTheChosenSpeedAndRange() throws Exception {
        long t0 = System.currentTimeMillis() * 1000 - 60_000_000;
        try (LoggerClient client = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(), "replayed"))) {
            for (int n = 0; n < 3; n++) {
                client.accept(new NodeNamedEvent(n, t0 - 10 + n, NodeKind.DATA, new NodeRef("replay", "Value" + n)));
            }
            for (int k = 0; k < 300; k++) {
                for (int n = 0; n < 3; n++) {
                    client.accept(new DataValueEvent(n, t0 + k * 10_000L + n, ValueType.DOUBLE, Double.toString(k * 10 + n)));
                }
            }
            assertThat(client.flush(60_000)).isTrue();
        }
        // a newer run, so the replayed one is a past run
        try (LoggerClient newer = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(), "newer"))) {
            newer.accept(new NodeNamedEvent(0, t0, NodeKind.DATA, new NodeRef("other", "X")));
            newer.accept(new DataValueEvent(0, t0 + 1, ValueType.DOUBLE, "1"));
            assertThat(newer.flush(60_000)).isTrue();
        }
        PlotData into = new PlotData();
        try (LoggerConnection viewer = new LoggerConnection(logger.viewerAddress(), new PlotData())) {
            List<RunInfo> runs = viewer.runs();
            RunInfo past = runs.stream().filter(r -> r.nodes().stream().anyMatch(n -> n.name().module().equals("replay")))
                    .findFirst().orElseThrow();
            assertThat(runs.get(0)).as("newest run first").isNotEqualTo(past);

            Replay whole = ReplayLoader.load(viewer, past, 0, 3600, 10, into).start();
            assertThat(whole.await(60_000)).isTrue();
            assertThat(whole.delivered()).isEqualTo(900);
            for (int n = 0; n < 3; n++) {
                Series.Samples s = seriesNamed(into, "replay/Value" + n).range(Long.MIN_VALUE, Long.MAX_VALUE);
                assertThat(s.size()).isEqualTo(300);
                for (int k = 0; k < 300; k++) {
                    assertThat(s.values()[k]).isEqualTo(k * 10 + n);
                }
            }

            // seconds 1 to 2 of the run, at 2x, paused and resumed on the way
            Replay part = ReplayLoader.load(viewer, past, 1.0, 2.0, 2, into).start();
            part.pause();
            assertThat(part.paused()).isTrue();
            part.setSpeed(10);
            part.resume();
            assertThat(part.await(60_000)).isTrue();
            Series.Samples s0 = seriesNamed(into, "replay/Value0").range(Long.MIN_VALUE, Long.MAX_VALUE);
            assertThat(s0.size()).isEqualTo(101); // k = 100 .. 200
            assertThat(s0.values()[0]).isEqualTo(1000);
            assertThat(s0.values()[100]).isEqualTo(2000);
            for (int i = 1; i < s0.size(); i++) {
                assertThat(s0.times()[i]).isGreaterThan(s0.times()[i - 1]);
            }

            // the last half second (negative from) before the run's last value (Value2, k = 299): Value0's k = 250 .. 299
            Replay last = ReplayLoader.load(viewer, past, -0.5, 0, 10, into).start();
            assertThat(last.await(60_000)).isTrue();
            Series.Samples s2 = seriesNamed(into, "replay/Value0").range(Long.MIN_VALUE, Long.MAX_VALUE);
            assertThat(s2.size()).isEqualTo(50);
            assertThat(s2.values()[0]).isEqualTo(2500);
            assertThat(s2.values()[49]).isEqualTo(2990);
        }
    }

    private static Series seriesNamed(PlotData data, String name) {
        return data.series().stream().filter(s -> s.name().equals(name)).findFirst().orElseThrow();
    }

    private static List<LoggedNode> newestRunNodesOnceNamed(LoggerConnection viewer, LoggerClient client, String node)
            throws Exception {
        long deadline = System.nanoTime() + TimeUnit.SECONDS.toNanos(60);
        while (System.nanoTime() < deadline) {
            client.flush(5_000);
            List<RunInfo> runs = viewer.runs();
            if (!runs.isEmpty() && runs.get(0).nodes().stream().anyMatch(n -> n.name().node().equals(node))) {
                return runs.get(0).nodes();
            }
            Thread.sleep(100);
        }
        throw new AssertionError("the logger never named " + node);
    }

    private static void waitUntilStill(List<NetworkEvent> events) throws InterruptedException {
        int before = -1;
        while (events.size() != before) {
            before = events.size();
            Thread.sleep(700);
        }
    }

    private static Map<Integer, List<NetworkEvent>> bySource(List<NetworkEvent> events) {
        Map<Integer, List<NetworkEvent>> m = new HashMap<>();
        for (NetworkEvent e : events) {
            m.computeIfAbsent(e.sourceId(), k -> new ArrayList<>()).add(e);
        }
        return m;
    }
}

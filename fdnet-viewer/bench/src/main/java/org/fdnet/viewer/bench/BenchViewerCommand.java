package org.fdnet.viewer.bench;

import java.awt.Graphics2D;
import java.awt.image.BufferedImage;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.Callable;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicLong;
import java.util.concurrent.locks.LockSupport;
import org.HdrHistogram.Histogram;
import org.HdrHistogram.Recorder;
import org.fdnet.logger.InProcessLogger;
import org.fdnet.event.DataValueEvent;
import org.fdnet.event.EventClock;
import org.fdnet.event.NodeNamedEvent;
import org.fdnet.event.TypedValue;
import org.fdnet.event.client.LoggerClient;
import org.fdnet.event.client.LoggerClientSettings;
import org.fdnet.netinfo.NodeKind;
import org.fdnet.netinfo.NodeRef;
import org.fdnet.viewer.data.NodeSelection;
import org.fdnet.viewer.data.PlotData;
import org.fdnet.viewer.source.LoggerConnection;
import org.fdnet.viewer.ui.PlotPanel;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;

/**
 * {@code fdnet bench viewer}: a real logger (embedded PostgreSQL), a writer feeding {@code --series} Datas
 * at {@code --rate} Hz each through the core's LoggerClient, and the viewer (LoggerConnection → PlotData →
 * PlotPanel) painting off-screen at its frame rate. Measures frames/s and the age of the newest drawn
 * value when a frame is finished (Data write → screen). Baselines of the same run: the raw monitor
 * stream's latency (write → viewer client, no painting), and the same painting of the same data, static.
 */
@Command(name = "viewer", mixinStandardHelpOptions = true,
        description = "Benchmark the viewer: N Datas at R Hz through a real logger, painted off-screen, beside baselines.")
public final class BenchViewerCommand implements Callable<Integer> {
    private static final java.lang.management.ThreadMXBean THREADS = java.lang.management.ManagementFactory.getThreadMXBean();

    @Option(names = "--series", defaultValue = "50", description = "Datas written (default ${DEFAULT-VALUE})")
    int series;

    @Option(names = "--rate", defaultValue = "1000", description = "values per second per Data (default ${DEFAULT-VALUE})")
    int rate;

    @Option(names = "--seconds", defaultValue = "30", description = "measured seconds after a 5 s warm-up (default ${DEFAULT-VALUE})")
    int seconds;

    @Option(names = "--size", defaultValue = "1200x700", description = "plot size in pixels (default ${DEFAULT-VALUE})")
    String size;

    @Option(names = "--window", defaultValue = "10", description = "seconds shown by the plot (default ${DEFAULT-VALUE})")
    double window;

    @Override
    public Integer call() throws Exception {
        String[] wh = size.split("x");
        int width = Integer.parseInt(wh[0]);
        int height = Integer.parseInt(wh[1]);
        System.out.printf("fdnet bench viewer: %d Datas x %,d Hz = %,d values/s, %d s measured (+5 s warm-up), plot %dx%d, %.0f s window%n",
                series, rate, series * rate, seconds, width, height, window);
        System.out.println("starting a logger on a throwaway embedded PostgreSQL ...");
        System.out.println("machine load at start: " + load());
        try (InProcessLogger logger = InProcessLogger.throwaway()) {
            Recorder stream = new Recorder(3);
            AtomicBoolean measuring = new AtomicBoolean();
            PlotData data = new PlotData();
            AtomicLong streamed = new AtomicLong();
            try (LoggerClient writer = new LoggerClient(LoggerClientSettings.defaults("127.0.0.1", logger.receiverPort(),
                    "bench-viewer-writer").withMemoryEvents(200_000));
                 LoggerConnection viewer = new LoggerConnection(logger.viewerAddress(), data, e -> {
                     streamed.incrementAndGet();
                     if (measuring.get()) {
                         stream.recordValue(Math.max(0, nowMicros() - e.time()));
                     }
                 })) {
                for (int i = 0; i < series; i++) {
                    writer.accept(new NodeNamedEvent(i, nowMicros(), NodeKind.DATA, new NodeRef("bench", "Data" + i)));
                }
                writer.flush(30_000);
                List<NodeSelection> chosen = new ArrayList<>();
                for (int i = 0; i < series; i++) {
                    chosen.add(new NodeSelection("bench/Data" + i, i % 2 == 0 ? "rad" : "N"));
                }
                viewer.watch(chosen);
                AtomicBoolean writing = new AtomicBoolean(true);
                AtomicLong written = new AtomicLong();
                Thread writerThread = new Thread(() -> write(writer, writing, written), "bench-viewer-writer");
                writerThread.start();
                PlotPanel plot = new PlotPanel(data);
                plot.setWindowMicros((long) (window * 1e6));
                plot.setCursorX(width / 2);
                BufferedImage image = new BufferedImage(width, height, BufferedImage.TYPE_INT_RGB);
                System.out.println("warming up 5 s ...");
                paintFor(plot, image, 5, null, null, null);
                measuring.set(true);
                stream.reset();
                long streamedBefore = streamed.get();
                long writtenBefore = written.get();
                Histogram latency = new Histogram(3);
                Histogram paint = new Histogram(3);
                Histogram paintCpu = new Histogram(3);
                long t0 = System.nanoTime();
                int frames = paintFor(plot, image, seconds, latency, paint, paintCpu);
                double elapsed = (System.nanoTime() - t0) / 1e9;
                measuring.set(false);
                writing.set(false);
                writerThread.join();
                Histogram raw = stream.getIntervalHistogram();
                long valuesWritten = written.get() - writtenBefore;
                System.out.printf("writer: %,d values in %.1f s = %,.0f values/s (target %,d)%n", valuesWritten, elapsed,
                        valuesWritten / elapsed, series * rate);
                System.out.printf("viewer: %,d values streamed in %.1f s; %d series, %,d samples held%n",
                        streamed.get() - streamedBefore, elapsed, data.series().size(),
                        data.series().stream().mapToLong(s -> s.size()).sum());
                System.out.printf("VIEWER frames: %d in %.1f s = %.1f frames/s (target >= 25, paced at %d); paint wall p50 %.1f ms,"
                        + " p99 %.1f ms; paint CPU p50 %.1f ms, p99 %.1f ms (the thread's own CPU time: what the load does not inflate)%n",
                        frames, elapsed, frames / elapsed, PlotPanel.FRAMES_PER_SECOND, paint.getValueAtPercentile(50) / 1000.0,
                        paint.getValueAtPercentile(99) / 1000.0, paintCpu.getValueAtPercentile(50) / 1000.0,
                        paintCpu.getValueAtPercentile(99) / 1000.0);
                System.out.printf("VIEWER write -> screen (newest drawn value's age at frame end): p50 %.1f ms, p99 %.1f ms, max %.1f ms (target < 1000 ms)%n",
                        latency.getValueAtPercentile(50) / 1000.0, latency.getValueAtPercentile(99) / 1000.0,
                        latency.getMaxValue() / 1000.0);
                System.out.printf("baseline raw monitor stream, write -> viewer client (values decoded into their series), no painting: p50 %.1f ms, p99 %.1f ms, max %.1f ms (%,d values)%n",
                        raw.getValueAtPercentile(50) / 1000.0, raw.getValueAtPercentile(99) / 1000.0,
                        raw.getMaxValue() / 1000.0, raw.getTotalCount());
                plot.setPaused(true);
                Histogram staticPaint = new Histogram(3);
                Histogram staticCpu = new Histogram(3);
                long s0 = System.nanoTime();
                int staticFrames = 0;
                while (System.nanoTime() - s0 < 5_000_000_000L) {
                    long p0 = System.nanoTime();
                    long c0 = THREADS.getCurrentThreadCpuTime();
                    paintOnce(plot, image);
                    staticPaint.recordValue((System.nanoTime() - p0) / 1000);
                    staticCpu.recordValue(Math.max(1, (THREADS.getCurrentThreadCpuTime() - c0) / 1000));
                    staticFrames++;
                }
                System.out.printf("baseline static painting of the same data (writer stopped, as fast as possible): %.1f frames/s, paint wall p50 %.1f ms, p99 %.1f ms; paint CPU p50 %.1f ms%n",
                        staticFrames / ((System.nanoTime() - s0) / 1e9), staticPaint.getValueAtPercentile(50) / 1000.0,
                        staticPaint.getValueAtPercentile(99) / 1000.0, staticCpu.getValueAtPercentile(50) / 1000.0);
                System.out.printf("RATIO live paint CPU p50 / static paint CPU p50 = %.2f; screen latency p50 - stream latency p50 = %.1f ms%n",
                        paintCpu.getValueAtPercentile(50) / (double) Math.max(1, staticCpu.getValueAtPercentile(50)),
                        (latency.getValueAtPercentile(50) - raw.getValueAtPercentile(50)) / 1000.0);
            }
        }
        System.out.println("machine load at end: " + load());
        return 0;
    }

    /**
     * Stamps the producer's ticks as an engine stamps values: unique and increasing per source even when a late
     * thread catches up several ticks within one microsecond (two equal stamps of one source are one key twice).
     */
    private void write(LoggerClient writer, AtomicBoolean writing, AtomicLong written) {
        EventClock stamps = new EventClock();
        long period = 1_000_000_000L / rate;
        long next = System.nanoTime();
        long tick = 0;
        while (writing.get()) {
            long wait = next - System.nanoTime();
            if (wait > 0) {
                LockSupport.parkNanos(wait);
                continue;
            }
            long time = stamps.next();
            for (int i = 0; i < series; i++) {
                double value = Math.sin(tick * 0.002 * Math.PI + i * 0.3) * (1 + i % 5) + i % 7 * 0.1;
                writer.accept(new DataValueEvent(i, time, TypedValue.of(value)));
            }
            written.addAndGet(series);
            tick++;
            next += period;
            if (System.nanoTime() - next > 100_000_000L) {
                next = System.nanoTime(); // fell behind by 100 ms: skip ticks rather than burst
            }
        }
    }

    /** Paints at {@link PlotPanel#FRAMES_PER_SECOND} for that long; answers the frames painted. */
    private static int paintFor(PlotPanel plot, BufferedImage image, int seconds, Histogram latency, Histogram paint,
            Histogram cpu) {
        long frameNanos = 1_000_000_000L / PlotPanel.FRAMES_PER_SECOND;
        long end = System.nanoTime() + TimeUnit.SECONDS.toNanos(seconds);
        long next = System.nanoTime();
        int frames = 0;
        while (System.nanoTime() < end) {
            long wait = next - System.nanoTime();
            if (wait > 0) {
                LockSupport.parkNanos(wait);
                continue;
            }
            next += frameNanos;
            if (System.nanoTime() - next > frameNanos) {
                next = System.nanoTime();
            }
            long p0 = System.nanoTime();
            long c0 = THREADS.getCurrentThreadCpuTime();
            paintOnce(plot, image);
            long done = nowMicros();
            frames++;
            if (paint != null) {
                paint.recordValue((System.nanoTime() - p0) / 1000);
                cpu.recordValue(Math.max(1, (THREADS.getCurrentThreadCpuTime() - c0) / 1000));
                long newest = plot.newestPainted();
                if (newest != Long.MIN_VALUE) {
                    latency.recordValue(Math.max(0, done - newest));
                }
            }
        }
        return frames;
    }

    private static void paintOnce(PlotPanel plot, BufferedImage image) {
        Graphics2D g = image.createGraphics();
        plot.paintPlot(g, image.getWidth(), image.getHeight());
        g.dispose();
        java.awt.Toolkit.getDefaultToolkit().sync();
    }

    private static String load() {
        try {
            return java.nio.file.Files.readString(java.nio.file.Path.of("/proc/loadavg")).trim();
        } catch (java.io.IOException e) {
            return "unknown (" + e.getMessage() + ")";
        }
    }

    private static long nowMicros() {
        java.time.Instant now = java.time.Instant.now();
        return now.getEpochSecond() * 1_000_000L + now.getNano() / 1_000L;
    }
}

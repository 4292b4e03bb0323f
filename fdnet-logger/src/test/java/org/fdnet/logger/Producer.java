package org.fdnet.logger;

import java.util.concurrent.atomic.AtomicBoolean;
import org.fdnet.event.EventSink;

/** A core that keeps producing on its own thread (about {@code perMilli} events per millisecond) until stopped. */
final class Producer implements AutoCloseable {
    private final TestEvents events;
    private final EventSink sink;
    private final AtomicBoolean running = new AtomicBoolean(true);
    private final Thread thread;

    Producer(TestEvents events, EventSink sink, int perMilli) {
        this.events = events;
        this.sink = sink;
        events.name(sink);
        thread = new Thread(() -> {
            while (running.get()) {
                for (int i = 0; i < perMilli; i++) {
                    events.produce(sink);
                }
                try {
                    Thread.sleep(1);
                } catch (InterruptedException e) {
                    return;
                }
            }
        }, "test-producer");
        thread.start();
    }

    /** Stops and returns how many events were produced (names not counted). */
    long stop() throws InterruptedException {
        running.set(false);
        thread.join();
        return events.produced();
    }

    @Override
    public void close() throws InterruptedException {
        stop();
    }
}

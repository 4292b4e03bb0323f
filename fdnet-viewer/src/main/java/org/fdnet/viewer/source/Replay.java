package org.fdnet.viewer.source;

import java.util.List;
import java.util.function.Consumer;
import org.fdnet.event.NetworkEvent;
import org.slf4j.Logger;
import org.slf4j.LoggerFactory;

/**
 * Plays recorded events (a past run's history, in time order) into a consumer at a chosen speed: at 1×
 * an event recorded {@code d} µs after the first one is delivered {@code d} µs after the start, at 10× ten
 * times sooner. {@link #pause()} holds the clock, {@link #setSpeed} changes the speed from now on (no jump).
 * Every event is delivered exactly once, in the recorded order, on the replay's own thread.
 */
public final class Replay {
    private static final Logger LOG = LoggerFactory.getLogger(Replay.class);

    private final List<NetworkEvent> events;
    private final Consumer<NetworkEvent> into;
    private final Thread thread;
    private final Object lock = new Object();
    private double speed;
    private boolean paused;
    private boolean stopped;
    /** Recorded time (µs) reached at wall time {@link #anchorNanos}. */
    private long anchorRecorded;
    private long anchorNanos;
    private volatile int delivered;
    private volatile boolean finished;

    public Replay(List<NetworkEvent> events, double speed, Consumer<NetworkEvent> into) {
        if (!(speed > 0)) {
            throw new IllegalArgumentException("replay speed " + speed + ": must be above 0 (1, 2, 10 …)");
        }
        this.events = List.copyOf(events);
        this.speed = speed;
        this.into = into;
        thread = new Thread(this::play, "fdnet-viewer-replay");
        thread.setDaemon(true);
    }

    public Replay start() {
        synchronized (lock) {
            anchorRecorded = events.isEmpty() ? 0 : events.get(0).time();
            anchorNanos = System.nanoTime();
        }
        thread.start();
        return this;
    }

    /** The recorded time (µs) the replay has reached now. */
    public long position() {
        synchronized (lock) {
            return paused ? anchorRecorded : anchorRecorded + (long) ((System.nanoTime() - anchorNanos) / 1000.0 * speed);
        }
    }

    public void pause() {
        synchronized (lock) {
            if (!paused) {
                anchorRecorded = position();
                paused = true;
            }
        }
    }

    public void resume() {
        synchronized (lock) {
            if (paused) {
                paused = false;
                anchorNanos = System.nanoTime();
                lock.notifyAll();
            }
        }
    }

    public boolean paused() {
        synchronized (lock) {
            return paused;
        }
    }

    public void setSpeed(double newSpeed) {
        if (!(newSpeed > 0)) {
            throw new IllegalArgumentException("replay speed " + newSpeed + ": must be above 0");
        }
        synchronized (lock) {
            anchorRecorded = position();
            anchorNanos = System.nanoTime();
            speed = newSpeed;
            lock.notifyAll();
        }
    }

    public double speed() {
        synchronized (lock) {
            return speed;
        }
    }

    public int total() {
        return events.size();
    }

    public int delivered() {
        return delivered;
    }

    public boolean finished() {
        return finished;
    }

    /** Waits until every event is delivered or the replay is stopped. */
    public boolean await(long millis) throws InterruptedException {
        thread.join(millis);
        return finished;
    }

    public void stop() {
        synchronized (lock) {
            stopped = true;
            lock.notifyAll();
        }
        thread.interrupt();
    }

    private void play() {
        try {
            for (NetworkEvent e : events) {
                synchronized (lock) {
                    while (!stopped && (paused || position() < e.time())) {
                        if (paused) {
                            lock.wait();
                        } else {
                            long waitMicros = (long) ((e.time() - position()) / speed);
                            lock.wait(Math.max(1, Math.min(50, waitMicros / 1000)));
                        }
                    }
                    if (stopped) {
                        return;
                    }
                }
                into.accept(e);
                delivered++;
            }
            finished = true;
        } catch (InterruptedException e) {
            LOG.debug("replay stopped after {} of {} events", delivered, events.size());
        }
    }
}

package org.fdnet.event.client;

import java.nio.file.Path;
import java.time.Duration;
import java.util.Objects;

/**
 * How a core talks to its logger.
 *
 * @param host            the logger's receiver address
 * @param port            the logger's receiver port (5555 by default)
 * @param coreName        shown in the logger's client list and stored with the run
 * @param memoryEvents    events kept in memory (sent or not) before new ones spill to the journal
 * @param journalDirectory where the spill journal lives (deleted on close)
 * @param journalBytes    the journal's bound; beyond it events are lost, counted and reported
 * @param reconnectDelay  wait between attempts to reach an absent logger
 * @param flushTimeout    how long {@link LoggerClient#flush()} and close wait for the logger's commits
 * @param silenceTimeout  a connection on which the logger sent nothing for this long — not even the ACK it repeats
 *                        every {@value org.fdnet.event.wire.Protocol#ACK_HEARTBEAT_MILLIS} ms — is dead: it is closed
 *                        and made again, and everything not acknowledged is sent again (a silent network drops
 *                        packets without a reset, and TCP alone would keep the connection for many minutes)
 */
public record LoggerClientSettings(String host, int port, String coreName, int memoryEvents,
                                   Path journalDirectory, long journalBytes, Duration reconnectDelay,
                                   Duration flushTimeout, Duration silenceTimeout) {
    /** Five heartbeats: a logger that stalls for a second or two (a long garbage collection) is not cut off. */
    public static final Duration DEFAULT_SILENCE_TIMEOUT = Duration.ofSeconds(5);

    /**
     * Checks the settings.
     *
     * @param host             the logger's receiver address, not null
     * @param port             the receiver port, 1 to 65535
     * @param coreName         the core's name, not null
     * @param memoryEvents     events kept in memory, at least 1000
     * @param journalDirectory where the journal lives, not null
     * @param journalBytes     the journal's bound, at least 0 (0: no journal)
     * @param reconnectDelay   wait between attempts to reach the logger
     * @param flushTimeout     how long a flush waits for commits
     * @param silenceTimeout   how long a connection may be silent before it is taken for dead, more than the heartbeat
     * @throws IllegalArgumentException when a number is out of its range, naming it
     */
    public LoggerClientSettings {
        Objects.requireNonNull(host, "host");
        Objects.requireNonNull(coreName, "coreName");
        Objects.requireNonNull(journalDirectory, "journalDirectory");
        if (port < 1 || port > 65535) {
            throw new IllegalArgumentException("port must be within 1..65535, was " + port);
        }
        if (memoryEvents < 1000) {
            throw new IllegalArgumentException("memoryEvents must be at least 1000, was " + memoryEvents);
        }
        if (journalBytes < 0) {
            throw new IllegalArgumentException("journalBytes must be at least 0, was " + journalBytes);
        }
        Objects.requireNonNull(silenceTimeout, "silenceTimeout");
        if (silenceTimeout.toMillis() <= org.fdnet.event.wire.Protocol.ACK_HEARTBEAT_MILLIS
                || silenceTimeout.toMillis() > Integer.MAX_VALUE) {
            throw new IllegalArgumentException("silenceTimeout must be longer than the logger's heartbeat ("
                    + org.fdnet.event.wire.Protocol.ACK_HEARTBEAT_MILLIS + " ms), was " + silenceTimeout.toMillis() + " ms");
        }
    }

    /**
     * Defaults: 200,000 events in memory, a 1 GiB journal under the temp directory, 500 ms reconnect, 60 s flush,
     * a connection silent for {@link #DEFAULT_SILENCE_TIMEOUT} taken for dead.
     *
     * @param host     the logger's receiver address
     * @param port     the receiver port
     * @param coreName the core's name for the logger
     * @return the settings, with a journal directory of this process's own
     */
    public static LoggerClientSettings defaults(String host, int port, String coreName) {
        Path dir = Path.of(System.getProperty("java.io.tmpdir"), "fdnet-journal-" + ProcessHandle.current().pid()
                + "-" + System.nanoTime());
        return new LoggerClientSettings(host, port, coreName, 200_000, dir, 1L << 30,
                Duration.ofMillis(500), Duration.ofSeconds(60), DEFAULT_SILENCE_TIMEOUT);
    }

    /**
     * These settings with another memory bound.
     *
     * @param events events kept in memory, at least 1000
     * @return new settings
     * @throws IllegalArgumentException when {@code events} is below 1000
     */
    public LoggerClientSettings withMemoryEvents(int events) {
        return new LoggerClientSettings(host, port, coreName, events, journalDirectory, journalBytes, reconnectDelay, flushTimeout, silenceTimeout);
    }

    /**
     * These settings with another journal.
     *
     * @param directory where the journal lives
     * @param bytes     its bound, at least 0
     * @return new settings
     * @throws IllegalArgumentException when {@code bytes} is negative
     */
    public LoggerClientSettings withJournal(Path directory, long bytes) {
        return new LoggerClientSettings(host, port, coreName, memoryEvents, directory, bytes, reconnectDelay, flushTimeout, silenceTimeout);
    }

    /**
     * These settings with another flush timeout.
     *
     * @param timeout how long a flush and close wait for the logger's commits
     * @return new settings
     */
    public LoggerClientSettings withFlushTimeout(Duration timeout) {
        return new LoggerClientSettings(host, port, coreName, memoryEvents, journalDirectory, journalBytes, reconnectDelay, timeout, silenceTimeout);
    }

    /**
     * Parses {@code HOST:PORT} (the form of {@code fdnet run --logger}).
     *
     * @param hostPort the address, e.g. {@code 127.0.0.1:5555}
     * @param coreName the core's name for the logger
     * @return the {@link #defaults} for that address
     * @throws IllegalArgumentException when the text is not {@code HOST:PORT} or the port not a number in range
     */
    public static LoggerClientSettings parseAddress(String hostPort, String coreName) {
        int colon = hostPort.lastIndexOf(':');
        if (colon <= 0 || colon == hostPort.length() - 1) {
            throw new IllegalArgumentException("logger address must be HOST:PORT, was '" + hostPort + "'");
        }
        int port;
        try {
            port = Integer.parseInt(hostPort.substring(colon + 1));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("logger port must be a number, was '" + hostPort.substring(colon + 1) + "'", e);
        }
        return defaults(hostPort.substring(0, colon), port, coreName);
    }
}

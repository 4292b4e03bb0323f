package org.fdnet.logger.config;

import java.nio.file.Path;
import java.util.EnumMap;
import java.util.Map;
import org.fdnet.netinfo.ValueRange;

/**
 * The logger's configuration: every parameter of the thesis's panels, validated when set with a message
 * naming the parameter, the rule and the value ({@code "writer.batchSize must be in [1, 1000000], was 0"}, worded by
 * {@link ValueRange} as node parameters are),
 * and sealed when the logger starts: a started logger's settings cannot change under it.
 *
 * <p>Values are kept as text keyed by {@link LoggerSetting} (so the file, the command line and the panel
 * share one path, {@link #set}); the typed getters parse what {@link #set} already checked.
 */
public final class LoggerConfig {
    private final Map<LoggerSetting, String> values = new EnumMap<>(LoggerSetting.class);
    private volatile boolean sealed;

    public LoggerConfig() {
        for (LoggerSetting s : LoggerSetting.values()) {
            values.put(s, s.defaultValue());
        }
    }

    public LoggerConfig copy() {
        LoggerConfig c = new LoggerConfig();
        c.values.putAll(values);
        return c;
    }

    /** Sets a parameter from text; throws {@link IllegalArgumentException} with a precise message. */
    public synchronized LoggerConfig set(LoggerSetting setting, String value) {
        if (sealed) {
            throw new IllegalStateException("the logger's configuration is sealed while it runs; stop it to change "
                    + setting.key());
        }
        String v = value == null ? "" : value.trim();
        validate(setting, v);
        values.put(setting, v);
        return this;
    }

    /**
     * Changes a {@link LoggerSetting#live() live} setting, also while sealed (the running logger reads it again);
     * any other setting is refused while sealed, as by {@link #set}.
     */
    public synchronized LoggerConfig setLive(LoggerSetting setting, String value) {
        if (!setting.live()) {
            return set(setting, value);
        }
        String v = value == null ? "" : value.trim();
        validate(setting, v);
        values.put(setting, v);
        return this;
    }

    /**
     * Checks one value against its setting's rule without keeping it (the panel checks as the user types).
     *
     * @throws IllegalArgumentException with the same message {@link #set} gives
     */
    public static void check(LoggerSetting setting, String value) {
        validate(setting, value == null ? "" : value.trim());
    }

    public synchronized String get(LoggerSetting setting) {
        return values.get(setting);
    }

    /** Seals after checking the rules between parameters ({@link #validate}). */
    public synchronized void seal() {
        validate();
        sealed = true;
    }

    /** The rules that join two parameters: the normal level must lie below the critical level. */
    public synchronized void validate() {
        checkLevels();
    }

    public boolean isSealed() {
        return sealed;
    }

    private static void validate(LoggerSetting s, String v) {
        switch (s) {
            case DATABASE_EMBEDDED, DATABASE_FSYNC, WRITER_RECONNECT, PRIORITY_ENABLED -> {
                if (!v.equals("true") && !v.equals("false")) {
                    throw new IllegalArgumentException(s.key() + " must be true or false, was '" + v + "'");
                }
            }
            case DATABASE_URL -> {
                if (!v.isEmpty() && !v.startsWith("jdbc:postgresql:")) {
                    throw new IllegalArgumentException(s.key() + " must start with jdbc:postgresql:, was '" + v + "'");
                }
            }
            case DATABASE_HOST, DATABASE_NAME, DATABASE_USER, RECEIVER_ADDRESS, SENDER_ADDRESS, DATABASE_DIRECTORY -> {
                if (v.isEmpty()) {
                    throw new IllegalArgumentException(s.key() + " must not be empty");
                }
            }
            case DATABASE_PORT -> range(s, v, 1, 65535);
            case RECEIVER_PORT, SENDER_PORT -> range(s, v, 0, 65535); // 0: any free port (tests, benchmarks)
            case WRITER_DELAY -> range(s, v, 0, 3_600_000);
            case WRITER_BATCH_SIZE -> range(s, v, 1, 1_000_000);
            case WRITER_BATCH_TIMEOUT -> range(s, v, 1, 3_600_000);
            case WRITER_MAX_BATCH_ROWS -> range(s, v, 1, 10_000_000);
            case WRITER_MAX_BATCH_BYTES -> range(s, v, 1, 4096);
            case WRITER_CONNECTIONS -> range(s, v, 1, 8);
            case WRITER_BACKEND_NICENESS -> range(s, v, 0, 19);
            case WRITER_RECONNECT_ATTEMPTS -> range(s, v, 1, 1_000_000);
            case WRITER_RECONNECT_DELAY -> range(s, v, 0, 3_600_000);
            case RECEIVER_MAX_CLIENTS, SENDER_MAX_CLIENTS -> range(s, v, 1, 10_000);
            case SENDER_QUERY_PAUSE -> range(s, v, 0, 1000);
            case RECEIVER_MAX_FRAME -> range(s, v, 1024, 64 << 20);
            case MEMORY_NETWORK_EVENT_BYTES, MEMORY_COMMAND_EVENT_BYTES -> range(s, v, 16, 1_000_000);
            case MEMORY_CAPACITY_MB -> range(s, v, 1, 1_000_000);
            case PRIORITY_CRITICAL, PRIORITY_NORMAL -> range(s, v, 1, 100);
            case DATABASE_PASSWORD -> {
            }
            default -> throw new IllegalStateException("no rule for " + s);
        }
    }

    private static void range(LoggerSetting s, String v, long min, long max) {
        long n;
        try {
            n = Long.parseLong(v);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException(s.key() + " must be a whole number, was '" + v + "'", e);
        }
        ValueRange.closed(min, max).check(s.key(), n, "");
    }

    private void checkLevels() {
        long critical = Long.parseLong(values.get(LoggerSetting.PRIORITY_CRITICAL));
        long normal = Long.parseLong(values.get(LoggerSetting.PRIORITY_NORMAL));
        if (normal >= critical) {
            throw new IllegalArgumentException(LoggerSetting.PRIORITY_NORMAL.key() + " must be below "
                    + LoggerSetting.PRIORITY_CRITICAL.key() + " (" + critical + "), was " + normal);
        }
    }

    private long number(LoggerSetting s) {
        return Long.parseLong(get(s));
    }

    public boolean embeddedDatabase() {
        return Boolean.parseBoolean(get(LoggerSetting.DATABASE_EMBEDDED)) && get(LoggerSetting.DATABASE_URL).isEmpty();
    }

    public Path embeddedDirectory() {
        String d = get(LoggerSetting.DATABASE_DIRECTORY);
        return d.startsWith("~/") ? Path.of(System.getProperty("user.home"), d.substring(2)) : Path.of(d);
    }

    /** The JDBC URL of the external database: {@code database.url}, else built from host, port and name. */
    public String jdbcUrl() {
        String url = get(LoggerSetting.DATABASE_URL);
        return url.isEmpty() ? "jdbc:postgresql://" + get(LoggerSetting.DATABASE_HOST) + ":"
                + get(LoggerSetting.DATABASE_PORT) + "/" + get(LoggerSetting.DATABASE_NAME) : url;
    }

    public String databaseName() {
        return get(LoggerSetting.DATABASE_NAME);
    }

    public String databaseUser() {
        return get(LoggerSetting.DATABASE_USER);
    }

    public String databasePassword() {
        return get(LoggerSetting.DATABASE_PASSWORD);
    }

    public long writingDelayMillis() {
        return number(LoggerSetting.WRITER_DELAY);
    }

    public int batchSize() {
        return (int) number(LoggerSetting.WRITER_BATCH_SIZE);
    }

    public boolean embeddedFsync() {
        return Boolean.parseBoolean(get(LoggerSetting.DATABASE_FSYNC));
    }

    public int maxBatchRows() {
        return (int) number(LoggerSetting.WRITER_MAX_BATCH_ROWS);
    }

    /** Writer connections with a batch in flight at once (commits stay in order). */
    public int writerConnections() {
        return (int) number(LoggerSetting.WRITER_CONNECTIONS);
    }

    public long maxBatchBytes() {
        return number(LoggerSetting.WRITER_MAX_BATCH_BYTES) << 20;
    }

    public long batchTimeoutMillis() {
        return number(LoggerSetting.WRITER_BATCH_TIMEOUT);
    }

    public boolean reconnect() {
        return Boolean.parseBoolean(get(LoggerSetting.WRITER_RECONNECT));
    }

    public int reconnectAttempts() {
        return (int) number(LoggerSetting.WRITER_RECONNECT_ATTEMPTS);
    }

    public long reconnectDelayMillis() {
        return number(LoggerSetting.WRITER_RECONNECT_DELAY);
    }

    public String receiverAddress() {
        return get(LoggerSetting.RECEIVER_ADDRESS);
    }

    public int receiverPort() {
        return (int) number(LoggerSetting.RECEIVER_PORT);
    }

    public int receiverMaxClients() {
        return (int) number(LoggerSetting.RECEIVER_MAX_CLIENTS);
    }

    public int maxFrameBytes() {
        return (int) number(LoggerSetting.RECEIVER_MAX_FRAME);
    }

    public String senderAddress() {
        return get(LoggerSetting.SENDER_ADDRESS);
    }

    public int senderPort() {
        return (int) number(LoggerSetting.SENDER_PORT);
    }

    public int senderMaxClients() {
        return (int) number(LoggerSetting.SENDER_MAX_CLIENTS);
    }

    /** How long one pause of the writer or a receiver for a viewer's query lasts at most ({@code QueryPriority}). */
    /** The nice value the writer's PostgreSQL backends are given when the database is local (0: untouched). */
    public int backendNiceness() {
        return (int) number(LoggerSetting.WRITER_BACKEND_NICENESS);
    }

    public long queryPauseMillis() {
        return number(LoggerSetting.SENDER_QUERY_PAUSE);
    }

    public int networkEventBytes() {
        return (int) number(LoggerSetting.MEMORY_NETWORK_EVENT_BYTES);
    }

    public int commandEventBytes() {
        return (int) number(LoggerSetting.MEMORY_COMMAND_EVENT_BYTES);
    }

    public long cacheCapacityBytes() {
        return number(LoggerSetting.MEMORY_CAPACITY_MB) << 20;
    }

    public boolean priorityEnabled() {
        return Boolean.parseBoolean(get(LoggerSetting.PRIORITY_ENABLED));
    }

    public int criticalPercent() {
        return (int) number(LoggerSetting.PRIORITY_CRITICAL);
    }

    public int normalPercent() {
        return (int) number(LoggerSetting.PRIORITY_NORMAL);
    }
}

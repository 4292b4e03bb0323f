package org.fdnet.logger.config;

/**
 * Every parameter of the logger, with its key in the configuration file, its panel (the thesis's tabs) and
 * its default: the one place where configuration keys are spelled.
 */
public enum LoggerSetting {
    DATABASE_EMBEDDED("database.embedded", Panel.DATABASE, "true", "use the embedded PostgreSQL (no setup)"),
    DATABASE_DIRECTORY("database.embeddedDirectory", Panel.DATABASE, "~/.fdnet/logger-db", "embedded data folder"),
    DATABASE_FSYNC("database.embeddedFsync", Panel.DATABASE, "true",
            "embedded: fsync every commit (false: faster, throwaway runs only — an OS crash or power loss can lose acknowledged events or corrupt the data folder)"),
    DATABASE_URL("database.url", Panel.DATABASE, "", "JDBC URL; overrides host, port and name"),
    DATABASE_HOST("database.host", Panel.DATABASE, "127.0.0.1", "server address"),
    DATABASE_PORT("database.port", Panel.DATABASE, "5432", "server port"),
    DATABASE_NAME("database.name", Panel.DATABASE, "fdnet", "database name"),
    DATABASE_USER("database.user", Panel.DATABASE, "postgres", "user name"),
    DATABASE_PASSWORD("database.password", Panel.DATABASE, "", "password"),

    WRITER_DELAY("writer.writingDelayMillis", Panel.WRITER, "0", "keep events this long in the cache before writing"),
    WRITER_BATCH_SIZE("writer.batchSize", Panel.WRITER, "1000", "events per COPY transaction"),
    WRITER_BATCH_TIMEOUT("writer.batchTimeoutMillis", Panel.WRITER, "2000", "write a partial batch after this long"),
    WRITER_MAX_BATCH_ROWS("writer.maxBatchRows", Panel.WRITER, "200000", "under backlog, batches grow up to this many events"),
    WRITER_MAX_BATCH_BYTES("writer.maxBatchMegabytes", Panel.WRITER, "64", "... and up to this many cached MB"),
    WRITER_CONNECTIONS("writer.connections", Panel.WRITER, "2",
            "under backlog, COPY the next batch on another connection while one commits (1: one batch at a time)"),
    WRITER_BACKEND_NICENESS("writer.backendNiceness", Panel.WRITER, "0",
            "the nice value of the writer's PostgreSQL backends when the database runs on this host, so viewers' queries"
            + " and the network go first (0: leave them)"),
    WRITER_RECONNECT("writer.reconnect", Panel.WRITER, "true", "reconnect to a lost database"),
    WRITER_RECONNECT_ATTEMPTS("writer.reconnectAttempts", Panel.WRITER, "5", "attempts before reporting the database down"),
    WRITER_RECONNECT_DELAY("writer.reconnectDelayMillis", Panel.WRITER, "5000", "delay between attempts"),

    RECEIVER_ADDRESS("receiver.address", Panel.RECEIVER, "127.0.0.1", "address the core server binds"),
    RECEIVER_PORT("receiver.port", Panel.RECEIVER, "5555", "port for cores"),
    RECEIVER_MAX_CLIENTS("receiver.maxClients", Panel.RECEIVER, "100", "cores served at once"),
    RECEIVER_MAX_FRAME("receiver.maxFrameBytes", Panel.RECEIVER, "1048576", "largest frame accepted"),

    SENDER_ADDRESS("sender.address", Panel.SENDER, "127.0.0.1", "address the viewer server binds"),
    SENDER_PORT("sender.port", Panel.SENDER, "5556", "port for viewers"),
    SENDER_MAX_CLIENTS("sender.maxClients", Panel.SENDER, "100", "viewers served at once"),
    SENDER_QUERY_PAUSE("sender.queryPauseMillis", Panel.SENDER, "0",
            "while a viewer's query is answered, the writer's COPY and the receivers pause up to this long (0: never)"),

    MEMORY_NETWORK_EVENT_BYTES("memory.networkEventBytes", Panel.MEMORY, "167", "bytes counted per state event (+ value)"),
    MEMORY_COMMAND_EVENT_BYTES("memory.commandEventBytes", Panel.MEMORY, "223", "bytes counted per command event"),
    MEMORY_CAPACITY_MB("memory.cacheCapacityMegabytes", Panel.MEMORY, "512", "cache capacity"),
    PRIORITY_ENABLED("priority.enabled", Panel.MEMORY, "true", "raise the writer's priority at the critical level; answer viewers from real-time threads (where permitted)"),
    PRIORITY_CRITICAL("priority.criticalPercent", Panel.MEMORY, "80", "critical level, % of capacity"),
    PRIORITY_NORMAL("priority.normalPercent", Panel.MEMORY, "50", "normal level, % of capacity");

    /** The thesis's panels, in the order of the tabs. */
    public enum Panel {
        DATABASE("Database"), WRITER("Logger writer"), RECEIVER("Server receiver"), SENDER("Server sender"),
        MEMORY("Memory & priority");

        private final String title;

        Panel(String title) {
            this.title = title;
        }

        public String title() {
            return title;
        }
    }

    private final String key;
    private final Panel panel;
    private final String defaultValue;
    private final String description;

    LoggerSetting(String key, Panel panel, String defaultValue, String description) {
        this.key = key;
        this.panel = panel;
        this.defaultValue = defaultValue;
        this.description = description;
    }

    public String key() {
        return key;
    }

    public Panel panel() {
        return panel;
    }

    public String defaultValue() {
        return defaultValue;
    }

    public String description() {
        return description;
    }

    public static LoggerSetting ofKey(String key) {
        for (LoggerSetting s : values()) {
            if (s.key.equals(key)) {
                return s;
            }
        }
        throw new IllegalArgumentException("unknown logger setting '" + key + "'");
    }
}

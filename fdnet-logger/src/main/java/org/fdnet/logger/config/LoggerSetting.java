package org.fdnet.logger.config;

/**
 * Every parameter of the logger, with its key in the configuration file, its panel (the thesis's tabs), its
 * default, and what the panel shows of it (a short label, the unit, a one-line help, the longer explanation):
 * the one place where configuration keys are spelled. A few settings are {@link #live()}: a running logger
 * takes a new value at once ({@link LoggerConfig#setLive}); the others wait for the next Start.
 */
public enum LoggerSetting {
    DATABASE_EMBEDDED("database.embedded", Panel.DATABASE, "true", "Embedded database", "",
            "start a PostgreSQL of our own (no setup)", "", false),
    DATABASE_DIRECTORY("database.embeddedDirectory", Panel.DATABASE, "~/.fdnet/logger-db", "Data folder", "",
            "where the embedded database keeps its files", "", false),
    DATABASE_FSYNC("database.embeddedFsync", Panel.DATABASE, "true", "Fsync commits", "",
            "off: faster, for throwaway runs only",
            "With false, an OS crash or power loss can lose acknowledged events or corrupt the data folder.", false),
    DATABASE_URL("database.url", Panel.DATABASE, "", "JDBC URL", "",
            "an external server; overrides host, port and name", "", false),
    DATABASE_HOST("database.host", Panel.DATABASE, "127.0.0.1", "Server host", "", "external server's address", "", false),
    DATABASE_PORT("database.port", Panel.DATABASE, "5432", "Server port", "", "external server's port", "", false),
    DATABASE_NAME("database.name", Panel.DATABASE, "fdnet", "Database", "", "database name on that server", "", false),
    DATABASE_USER("database.user", Panel.DATABASE, "postgres", "User", "", "user name on that server", "", false),
    DATABASE_PASSWORD("database.password", Panel.DATABASE, "", "Password", "", "kept in the configuration file", "", false),

    WRITER_DELAY("writer.writingDelayMillis", Panel.WRITER, "0", "Writing delay", "ms",
            "events stay cached this long before writing", "", true),
    WRITER_BATCH_SIZE("writer.batchSize", Panel.WRITER, "1000", "Batch size", "events",
            "events per COPY transaction", "", false),
    WRITER_BATCH_TIMEOUT("writer.batchTimeoutMillis", Panel.WRITER, "2000", "Batch timeout", "ms",
            "a partial batch is written after this long", "", true),
    WRITER_MAX_BATCH_ROWS("writer.maxBatchRows", Panel.WRITER, "200000", "Largest batch", "events",
            "under backlog, batches grow up to this", "", false),
    WRITER_MAX_BATCH_BYTES("writer.maxBatchMegabytes", Panel.WRITER, "64", "Largest batch size", "MB",
            "... and up to this many cached megabytes", "", false),
    WRITER_CONNECTIONS("writer.connections", Panel.WRITER, "2", "Connections", "",
            "batches in flight at once under backlog",
            "Under backlog, the next batch is copied on another connection while one commits (1: one batch at a time).",
            false),
    WRITER_BACKEND_NICENESS("writer.backendNiceness", Panel.WRITER, "0", "Backend niceness", "nice",
            "0: leave the database's writer processes alone",
            "The nice value of the writer's PostgreSQL backends when the database runs on this host, so viewers'"
            + " queries and the network go first.", false),
    WRITER_RECONNECT("writer.reconnect", Panel.WRITER, "true", "Reconnect", "", "reconnect to a lost database", "", false),
    WRITER_RECONNECT_ATTEMPTS("writer.reconnectAttempts", Panel.WRITER, "5", "Reconnect attempts", "",
            "before the database is reported down", "", true),
    WRITER_RECONNECT_DELAY("writer.reconnectDelayMillis", Panel.WRITER, "5000", "Reconnect delay", "ms",
            "between two attempts", "", true),

    RECEIVER_ADDRESS("receiver.address", Panel.RECEIVER, "127.0.0.1", "Address", "", "the cores' server binds this", "", false),
    RECEIVER_PORT("receiver.port", Panel.RECEIVER, "5555", "Port", "", "cores connect here (0: any free port)", "", false),
    RECEIVER_MAX_CLIENTS("receiver.maxClients", Panel.RECEIVER, "100", "Most cores", "", "cores served at once", "", false),
    RECEIVER_MAX_FRAME("receiver.maxFrameBytes", Panel.RECEIVER, "1048576", "Largest frame", "bytes",
            "a longer frame closes its connection", "", false),

    SENDER_ADDRESS("sender.address", Panel.SENDER, "127.0.0.1", "Address", "", "the viewers' server binds this", "", false),
    SENDER_PORT("sender.port", Panel.SENDER, "5556", "Port", "", "viewers connect here (0: any free port)", "", false),
    SENDER_MAX_CLIENTS("sender.maxClients", Panel.SENDER, "100", "Most viewers", "", "viewers served at once", "", false),
    SENDER_QUERY_PAUSE("sender.queryPauseMillis", Panel.SENDER, "0", "Query pause", "ms",
            "writing pauses this long for a query (0: never)",
            "While a viewer's query is answered, the writer's COPY and the receivers pause up to this long.", false),

    MEMORY_NETWORK_EVENT_BYTES("memory.networkEventBytes", Panel.MEMORY, "167", "State event", "bytes",
            "counted per state event (plus its value)", "", false),
    MEMORY_COMMAND_EVENT_BYTES("memory.commandEventBytes", Panel.MEMORY, "223", "Command event", "bytes",
            "counted per command event", "", false),
    MEMORY_CAPACITY_MB("memory.cacheCapacityMegabytes", Panel.MEMORY, "512", "Cache capacity", "MB",
            "the event cache's memory", "", false),
    PRIORITY_ENABLED("priority.enabled", Panel.MEMORY, "true", "Priorities", "",
            "raise the writer at the critical level",
            "Raise the writer's priority at the critical level; answer viewers from real-time threads (where permitted).",
            false),
    PRIORITY_CRITICAL("priority.criticalPercent", Panel.MEMORY, "80", "Critical level", "%",
            "of capacity: receivers pause, the writer speeds up", "", false),
    PRIORITY_NORMAL("priority.normalPercent", Panel.MEMORY, "50", "Normal level", "%",
            "of capacity: back to normal (below critical)", "", false);

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
    private final String label;
    private final String unit;
    private final String help;
    private final String details;
    private final boolean live;

    LoggerSetting(String key, Panel panel, String defaultValue, String label, String unit, String help, String details,
            boolean live) {
        this.key = key;
        this.panel = panel;
        this.defaultValue = defaultValue;
        this.label = label;
        this.unit = unit;
        this.help = help;
        this.details = details;
        this.live = live;
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

    /** A short name for the panel ("Batch size"). */
    public String label() {
        return label;
    }

    /** The unit of the value ("ms", "MB"), {@code ""} for none. */
    public String unit() {
        return unit;
    }

    /** One line shown beside the field. */
    public String help() {
        return help;
    }

    /** The whole explanation: the help line and, where one is needed, more ({@code ""} none). */
    public String description() {
        return details.isEmpty() ? help : help + ". " + details;
    }

    /** True when a running logger applies a new value at once; the others take effect at the next Start. */
    public boolean live() {
        return live;
    }

    /** True for a true/false setting. */
    public boolean isSwitch() {
        return "true".equals(defaultValue) || "false".equals(defaultValue);
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

package org.fdnet.logger.export;

import org.fdnet.event.ValueType;

/**
 * One recorded event on its way to a sink, reused from row to row (a million rows allocate no row objects):
 * a Data's value (its type and stored text), a Relation's value, or a structure change. {@code time} is µs on
 * the run's common clock (the host's offset already applied).
 */
public final class ExportRow {
    /** What the row is. */
    public enum Kind { DATA, RELATION, COMMAND }

    Kind kind;
    int sourceId;
    long time;
    ValueType type;
    String value;
    String sourceType;
    String command;
    String paramsId;
    String paramsType;

    public ExportRow data(int sourceId, long time, ValueType type, String value) {
        this.kind = Kind.DATA;
        this.sourceId = sourceId;
        this.time = time;
        this.type = type;
        this.value = value;
        return this;
    }

    public ExportRow relation(int sourceId, long time, String value) {
        this.kind = Kind.RELATION;
        this.sourceId = sourceId;
        this.time = time;
        this.type = null;
        this.value = value;
        return this;
    }

    public ExportRow command(int sourceId, long time, String sourceType, String command, String paramsId,
                             String paramsType) {
        this.kind = Kind.COMMAND;
        this.sourceId = sourceId;
        this.time = time;
        this.sourceType = sourceType;
        this.command = command;
        this.paramsId = paramsId;
        this.paramsType = paramsType;
        return this;
    }

    public Kind kind() {
        return kind;
    }

    public int sourceId() {
        return sourceId;
    }

    public long time() {
        return time;
    }

    /** A Data's value type (null for the other kinds). */
    public ValueType type() {
        return type;
    }

    /** The value as the database stores it (null when NULL). */
    public String value() {
        return value;
    }
}

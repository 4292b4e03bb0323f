package org.fdnet.bench.report;

import static org.fdnet.bench.report.FigureSpec.of;

import java.util.List;

/** What the report reads from {@code bench logger}'s summary (its lines {@code [1]} to {@code [4]}). */
final class LoggerFigures {
    private static final String NUM = "([0-9][0-9,]*(?:\\.[0-9]+)?)";
    private static final String P99 = "p50 / p99 / max: [0-9.,]+ / " + NUM;
    private static final String SUSTAINED = "\\[1\\] logger sustained, whole run: " + NUM + " events/s";
    private static final String KEYED_LIMIT = "\\[2\\] keyed-COPY limit with 2 connections at once .*?: " + NUM + " rows/s";
    private static final String IDLE_IN_PROCESS = "\\[4\\] query in-process, writer idle: " + P99;
    private static final String WRITER = "the writer's COPY into the keyed table on 2 shared cores";

    static final List<FigureSpec> FIGURES = List.of(
            of("logger: sustained end to end through TCP, fsync on", "events/s", SUSTAINED, KEYED_LIMIT,
                    Target.atLeast(500_000), false, WRITER),
            of("logger: sustained / keyed-COPY limit on the same connections", "events/s", SUSTAINED, KEYED_LIMIT,
                    Target.ratioAtLeast(0.75), false, "the cache, the receiver and the writer share the cores with PostgreSQL"),
            of("logger: sustained / raw COPY of the same batches", "events/s", SUSTAINED,
                    "\\[2\\] raw COPY, the writer's batch sizes, 2 connections pipelined, whole run: " + NUM + " rows/s",
                    Target.ratioAtLeast(0.8), false, "the cache, the receiver and the writer share the cores with PostgreSQL"),
            of("logger: events lost in the sustained run", "lost", "\\[1\\] loss counted in the database: " + NUM, null,
                    Target.atMost(0), true, "an acknowledged event is missing from the database"),
            of("logger: event → commit p99 at 50,000 events/s", "ms",
                    "\\[3\\] event-to-commit latency p99 at [0-9,]+ events/s: " + NUM + " ms", null,
                    Target.atMost(2500), true, "batches wait behind a backlog"),
            of("logger: events lost in the burst", "lost", "\\[4\\] burst loss counted in the database: " + NUM, null,
                    Target.atMost(0), true, "an acknowledged event is missing from the database"),
            of("logger: viewer query over TCP while the writer drains, p99", "ms",
                    "\\[4\\] query ViewerClient over TCP, while the writer drains: " + P99,
                    "\\[4\\] query in-process, while the writer drains: " + P99,
                    Target.atMost(2), true, "the first calls of the path and collections in the logger's JVM"),
            of("logger: query in-process while the writer drains, p99", "ms",
                    "\\[4\\] query in-process, while the writer drains: " + P99, IDLE_IN_PROCESS,
                    Target.atMost(1), true, "a collection in the logger's JVM during the queries"),
            of("logger: viewer query over TCP, writer idle, p99", "ms",
                    "\\[4\\] query ViewerClient over TCP, writer idle: " + P99, IDLE_IN_PROCESS,
                    Target.atMost(1), true, "the TCP round trip on a loaded machine"));

    private LoggerFigures() {
    }
}

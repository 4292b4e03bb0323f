package org.fdnet.logger.export;

import java.io.BufferedOutputStream;
import java.io.IOException;
import java.io.OutputStream;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.ServiceLoader;
import org.fdnet.event.ValueType;
import org.fdnet.netinfo.NodeKind;

/**
 * A run as one MCAP file: a channel per node ({@code /MODULE/NODE}, host and kind in its metadata) made at the
 * node's first row, JSON messages against a JSON Schema per value type, {@code log_time} the row's common-clock
 * time in ns; {@value #STRUCTURE_TOPIC} for structure changes and module loads; the run's identity and hosts as
 * metadata, the {@code .fdn} as an attachment; and the topics of any {@link SceneSource} that knows the run.
 */
public final class McapRunSink implements RunSink {
    public static final String STRUCTURE_TOPIC = "/fdnet/structure";
    public static final String LIBRARY = "fdnet export";
    /** Uncompressed bytes per chunk: a reader seeking by time decompresses about this much. */
    static final int CHUNK_BYTES = 1 << 20;
    private static final int RELATION_SLOT = 0; // ValueType codes are 1..6

    private final McapWriter mcap;
    private final Map<String, String> sceneOptions;
    private final RecordBuffer body = new RecordBuffer(256);
    private final Map<Integer, int[]> channelOf = new HashMap<>();
    private final int[] schemaOf = new int[8];
    private final List<ActiveScene> scenes = new ArrayList<>();
    private RecordedRun run;
    private int structureChannel;

    private record ActiveScene(RunScene scene, int[] channels) {
    }

    public McapRunSink(OutputStream out) throws IOException {
        this(out, Map.of());
    }

    /** {@code sceneOptions}: what the {@link SceneSource}s are told ({@code course=crossing} for RoQ). */
    public McapRunSink(OutputStream out, Map<String, String> sceneOptions) throws IOException {
        this.sceneOptions = Map.copyOf(sceneOptions);
        this.mcap = new McapWriter(new BufferedOutputStream(out, 1 << 16), "", LIBRARY, CHUNK_BYTES);
    }

    @Override
    public void begin(RecordedRun run) throws IOException {
        this.run = run;
        mcap.metadata("fdnet.run", run.identity());
        Map<String, String> hosts = new LinkedHashMap<>();
        for (RecordedNode n : run.nodes().values()) {
            if (!n.host().isEmpty()) {
                hosts.put(n.host(), "clock_offset_us=" + n.clockOffsetMicros());
            }
        }
        for (String h : run.hosts()) {
            hosts.putIfAbsent(h, "clock_offset_us=0");
        }
        mcap.metadata("fdnet.hosts", hosts);
        if (run.definition() != null) {
            mcap.attachment(run.network() + ".fdn", "application/xml", run.startedMicros() * 1000,
                    run.definition().getBytes(StandardCharsets.UTF_8));
        }
        int structureSchema = mcap.schema(MessageSchemas.STRUCTURE_NAME, MessageSchemas.ENCODING, MessageSchemas.structure());
        structureChannel = mcap.channel(structureSchema, STRUCTURE_TOPIC, "json", Map.of("kind", "structure"));
        for (SceneSource source : ServiceLoader.load(SceneSource.class)) {
            source.sceneOf(run, sceneOptions).ifPresent(this::addScene);
        }
    }

    private void addScene(RunScene scene) {
        List<RunScene.Topic> topics = scene.topics();
        int[] channels = new int[topics.size()];
        for (int i = 0; i < channels.length; i++) {
            RunScene.Topic t = topics.get(i);
            int schema = mcap.schema(t.schemaName(), MessageSchemas.ENCODING, t.jsonSchema().getBytes(StandardCharsets.UTF_8));
            channels[i] = mcap.channel(schema, t.topic(), "json", Map.of("kind", "scene"));
        }
        scenes.add(new ActiveScene(scene, channels));
    }

    @Override
    public void accept(ExportRow row) throws IOException {
        long nanos = row.time * 1000;
        body.clear();
        switch (row.kind) {
            case DATA -> {
                ValueJson.dataMessage(body, row.type, row.value);
                mcap.message(channel(row.sourceId, row.type), nanos, body.array(), 0, body.length());
            }
            case RELATION -> {
                body.ascii("{\"value\":");
                if (row.value == null) {
                    body.ascii("null");
                } else {
                    ValueJson.string(body, row.value);
                }
                body.ascii('}');
                mcap.message(channel(row.sourceId, null), nanos, body.array(), 0, body.length());
            }
            case COMMAND -> {
                body.ascii("{\"command\":");
                ValueJson.string(body, row.command);
                body.ascii(",\"source\":");
                RecordedNode source = run.node(row.sourceId);
                ValueJson.string(body, source.kind() == null ? row.sourceType : source.label());
                body.ascii(",\"source_type\":");
                ValueJson.string(body, row.sourceType);
                body.ascii(",\"params_id\":");
                ValueJson.string(body, row.paramsId);
                body.ascii(",\"params_type\":");
                ValueJson.string(body, row.paramsType);
                body.ascii('}');
                mcap.message(structureChannel, nanos, body.array(), 0, body.length());
            }
        }
        for (ActiveScene s : scenes) {
            s.scene().accept(row, (topic, logTime, json) -> emit(s.channels()[topic], logTime, json));
        }
    }

    private void emit(int channel, long logTimeNanos, String json) throws IOException {
        byte[] b = json.getBytes(StandardCharsets.UTF_8);
        mcap.message(channel, logTimeNanos, b, 0, b.length);
    }

    /** The channel of a node's values of one type (a Relation's: type null), made at its first row. */
    private int channel(int sourceId, ValueType type) {
        int[] byType = channelOf.computeIfAbsent(sourceId, id -> new int[8]);
        int slot = type == null ? RELATION_SLOT : type.code();
        if (byType[slot] == 0) {
            RecordedNode n = run.node(sourceId);
            if (schemaOf[slot] == 0) {
                schemaOf[slot] = type == null
                        ? mcap.schema(MessageSchemas.RELATION_NAME, MessageSchemas.ENCODING, MessageSchemas.relation())
                        : mcap.schema(MessageSchemas.nameOf(type), MessageSchemas.ENCODING, MessageSchemas.of(type));
            }
            Map<String, String> meta = new LinkedHashMap<>();
            meta.put("host", n.host());
            meta.put("module", n.module());
            meta.put("node", n.node());
            meta.put("kind", type == null || n.kind() == NodeKind.RELATION ? "relation" : "data");
            meta.put("source_id", Integer.toString(sourceId));
            meta.put("clock_offset_us", Long.toString(n.clockOffsetMicros()));
            if (type != null) {
                meta.put("value_type", type.name().toLowerCase(java.util.Locale.ROOT));
            }
            byType[slot] = mcap.channel(schemaOf[slot], n.topic(), "json", meta);
        }
        return byType[slot];
    }

    @Override
    public long written() {
        return mcap.messageCount();
    }

    @Override
    public int channels() {
        return mcap.channelCount();
    }

    @Override
    public long bytes() {
        return mcap.position();
    }

    @Override
    public void close() throws IOException {
        try {
            for (ActiveScene s : scenes) {
                s.scene().finish((topic, logTime, json) -> emit(s.channels()[topic], logTime, json));
            }
        } finally {
            mcap.close();
        }
    }
}

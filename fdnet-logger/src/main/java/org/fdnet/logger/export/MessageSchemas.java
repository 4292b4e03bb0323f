package org.fdnet.logger.export;

import java.nio.charset.StandardCharsets;
import org.fdnet.event.ValueType;

/**
 * The JSON Schemas (draft 2020-12) of the exported messages: one per Data value type, one for a Relation's
 * value and one for the network's structure changes. A reader decodes every message against the schema of its
 * channel; the names are what Foxglove shows as the channel's type.
 */
final class MessageSchemas {
    static final String ENCODING = "jsonschema";
    static final String STRUCTURE_NAME = "fdnet.NetworkCommand";
    static final String RELATION_NAME = "fdnet.RelationValue";

    private MessageSchemas() {
    }

    static String nameOf(ValueType type) {
        return switch (type) {
            case BOOLEAN -> "fdnet.BooleanValue";
            case LONG -> "fdnet.LongValue";
            case DOUBLE -> "fdnet.DoubleValue";
            case STRING -> "fdnet.StringValue";
            case BYTES -> "fdnet.BytesValue";
            case DOUBLES -> "fdnet.DoublesValue";
        };
    }

    static byte[] of(ValueType type) {
        String value = switch (type) {
            case BOOLEAN -> "{\"type\":[\"boolean\",\"string\",\"null\"]}";
            case LONG -> "{\"type\":[\"integer\",\"string\",\"null\"]}";
            case DOUBLE -> "{\"type\":[\"number\",\"string\",\"null\"],"
                    + "\"description\":\"NaN and infinities, which JSON has no number for, are the strings NaN, Infinity, -Infinity\"}";
            case STRING -> "{\"type\":[\"string\",\"null\"]}";
            case BYTES -> "{\"type\":[\"string\",\"null\"],\"contentEncoding\":\"base64\"}";
            case DOUBLES -> "{\"type\":[\"array\",\"null\"],\"items\":{\"type\":[\"number\",\"string\"]}}";
        };
        return object(nameOf(type), "A Data's value", "\"value\":" + value, "\"value\"");
    }

    static byte[] relation() {
        return object(RELATION_NAME, "A Relation's value", "\"value\":{\"type\":[\"string\",\"null\"]}", "\"value\"");
    }

    static byte[] structure() {
        return object(STRUCTURE_NAME, "A change of the running network's structure or of a module's state",
                "\"command\":{\"type\":\"string\",\"enum\":[\"create\",\"destroy\",\"connect\",\"disconnect\",\"load\","
                        + "\"unload\",\"hold\",\"resume\"]},"
                        + "\"source\":{\"type\":\"string\",\"description\":\"the issuing Relation, Module/Node, or the controller\"},"
                        + "\"source_type\":{\"type\":\"string\"},"
                        + "\"params_id\":{\"type\":\"string\",\"description\":\"a node, a connection or a module\"},"
                        + "\"params_type\":{\"type\":\"string\"}",
                "\"command\",\"source\",\"source_type\",\"params_id\",\"params_type\"");
    }

    private static byte[] object(String title, String description, String properties, String required) {
        return ("{\"$schema\":\"https://json-schema.org/draft/2020-12/schema\",\"title\":\"" + title
                + "\",\"description\":\"" + description + "\",\"type\":\"object\",\"properties\":{" + properties
                + "},\"required\":[" + required + "]}").getBytes(StandardCharsets.UTF_8);
    }
}

#!/usr/bin/env python3
"""Reads an MCAP file with the Python mcap package (the format's reference reader) and checks it whole.

  check_mcap.py FILE [--expect ROWS.jsonl] [--topic TOPIC]...

Checks: the summary and the chunk indexes are there and agree with the messages; every CRC (chunks, data
section, summary, attachments) is validated; messages are in log-time order in the file; every message decodes
as JSON and validates against its channel's JSON Schema; the given topics are present. With --expect (one JSON
object per database row: topic, log_time, kind, type, value, command fields) the messages must be exactly those
rows. Prints one line "python mcap: OK ..." or the first differences, exit 1.
"""
import argparse
import json
import math
import sys

import jsonschema
from mcap.reader import SeekingReader
from mcap.stream_reader import StreamReader

DOUBLE, DOUBLES, LONG, BOOLEAN = 3, 6, 2, 1


def canon(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return "nan" if math.isnan(v) else repr(v)
    if isinstance(v, int):
        return str(v)
    if isinstance(v, list):
        return "[" + ",".join(canon(x) for x in v) + "]"
    if v is None:
        return "null"
    if isinstance(v, dict):
        return json.dumps(v, sort_keys=True, ensure_ascii=False)
    return "s:" + v


def as_float(x):
    return float(x)  # a JSON number, or the strings NaN / Infinity / -Infinity


def expected_key(e):
    kind, text, t = e["kind"], e.get("value"), e.get("type")
    if kind == "command":
        v = {k: e[k] for k in ("command", "source_type", "params_id", "params_type")}
    elif text is None:
        v = None
    elif kind == "relation" or t in (4, 5):
        v = text
    elif t == BOOLEAN:
        v = text == "true"
    elif t == LONG:
        v = int(text)
    elif t == DOUBLE:
        v = float(text)
    elif t == DOUBLES:
        v = [float(x) for x in text.split(",")] if text else []
    else:
        raise ValueError("unknown value type %r" % t)
    return (e["topic"], int(e["log_time"]), canon(v))


def actual_key(channel, data):
    if channel.topic == "/fdnet/structure":
        v = {k: data[k] for k in ("command", "source_type", "params_id", "params_type")}
        return (channel.topic, canon(v))
    v = data["value"]
    vt = channel.metadata.get("value_type")
    if v is not None and vt == "double":
        v = as_float(v)
    elif v is not None and vt == "doubles":
        v = [as_float(x) for x in v]
    return (channel.topic, canon(v))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("file")
    ap.add_argument("--expect")
    ap.add_argument("--topic", action="append", default=[])
    args = ap.parse_args()
    problems = []

    # 1. every record, front to back, CRCs checked (chunks, data end, summary, attachments)
    with open(args.file, "rb") as f:
        records = {}
        for r in StreamReader(f, skip_magic=False, validate_crcs=True).records:
            records[type(r).__name__] = records.get(type(r).__name__, 0) + 1

    # 2. the indexed reader: summary, chunk indexes, messages in file order
    with open(args.file, "rb") as f:
        reader = SeekingReader(f, validate_crcs=True)
        summary = reader.get_summary()
        if summary is None or summary.statistics is None:
            print("python mcap: FAIL no summary/statistics in " + args.file)
            return 1
        validators = {}
        for sid, schema in summary.schemas.items():
            doc = json.loads(schema.data)
            validators[sid] = jsonschema.validators.validator_for(doc)(doc)
        actual = []
        last = -1
        topics = set()
        for schema, channel, message in reader.iter_messages(log_time_order=False):
            if message.log_time < last:
                problems.append("message on %s at %d comes after one at %d" % (channel.topic, message.log_time, last))
            last = message.log_time
            data = json.loads(message.data)
            errors = list(validators[schema.id].iter_errors(data))
            if errors:
                problems.append("%s at %d does not match %s: %s" % (channel.topic, message.log_time, schema.name, errors[0].message))
            topics.add(channel.topic)
            if channel.metadata.get("kind") != "scene":
                actual.append((channel.topic, message.log_time, actual_key(channel, data)[1]))
        stats = summary.statistics
        count = sum(1 for _ in reader.iter_messages(log_time_order=True))
        if stats.message_count != count:
            problems.append("statistics say %d messages, the reader found %d" % (stats.message_count, count))
        if stats.message_count > 0 and not summary.chunk_indexes:
            problems.append("messages but no chunk index")
        if sum(stats.channel_message_counts.values()) != stats.message_count:
            problems.append("per-channel counts do not add up to the message count")
        attachments = [a.name for a in reader.iter_attachments()]
        metadata = {m.name: m.metadata for m in reader.iter_metadata()}
        if "fdnet.run" not in metadata:
            problems.append("no fdnet.run metadata")
    for t in args.topic:
        if t not in topics:
            problems.append("no message on topic " + t)

    if args.expect:
        with open(args.expect, encoding="utf-8") as f:
            expected = sorted(expected_key(json.loads(line)) for line in f if line.strip())
        got = sorted(actual)
        if got != expected:
            missing = [e for e in expected if e not in set(got)][:3]
            extra = [a for a in got if a not in set(expected)][:3]
            problems.append("%d messages vs %d database rows; missing %s; unexpected %s" % (len(got), len(expected), missing, extra))

    if problems:
        print("python mcap: FAIL " + "; ".join(problems[:5]))
        return 1
    print("python mcap: OK %d messages, %d channels, %d chunks, %d attachments %s, metadata %s, rows %s" % (
        stats.message_count, len(summary.channels), len(summary.chunk_indexes), len(attachments), attachments,
        sorted(metadata), len(actual)))
    return 0


if __name__ == "__main__":
    sys.exit(main())

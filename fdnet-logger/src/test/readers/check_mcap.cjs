// Reads an MCAP file with @mcap/core's indexed reader (the TypeScript library Foxglove's app reads with).
//
//   NODE_PATH=.../node_modules node check_mcap.cjs FILE [--expect ROWS.jsonl] [--topic TOPIC]...
//
// Checks: summary, statistics and chunk indexes present; every message read through the chunk indexes with
// CRCs validated; counts agree with the statistics; each message validates against its channel's JSON Schema
// (ajv); the given topics are present; with --expect, the messages are exactly the database's rows.
// Prints one line "@mcap/core: OK ..." or the first differences, exit 1.
"use strict";
const fs = require("fs");
const { McapIndexedReader } = require("@mcap/core");
const fzstd = require("fzstd");
const Ajv2020 = require("ajv/dist/2020").default;

function canon(v) {
  if (typeof v === "boolean") return v ? "true" : "false";
  if (typeof v === "number") return Number.isNaN(v) ? "nan" : String(v);
  if (Array.isArray(v)) return "[" + v.map(canon).join(",") + "]";
  if (v === null || v === undefined) return "null";
  if (typeof v === "object") return JSON.stringify(Object.keys(v).sort().map((k) => [k, v[k]]));
  return "s:" + v;
}

function expectedKey(e) {
  let v;
  if (e.kind === "command") v = { command: e.command, source_type: e.source_type, params_id: e.params_id, params_type: e.params_type };
  else if (e.value === null || e.value === undefined) v = null;
  else if (e.kind === "relation" || e.type === 4 || e.type === 5) v = e.value;
  else if (e.type === 1) v = e.value === "true";
  else if (e.type === 2 || e.type === 3) v = Number(e.value);
  else if (e.type === 6) v = e.value === "" ? [] : e.value.split(",").map(Number);
  else throw new Error("unknown value type " + e.type);
  return e.topic + "\t" + e.log_time + "\t" + canon(v);
}

function actualKey(channel, logTime, data) {
  let v;
  if (channel.topic === "/fdnet/structure") {
    v = { command: data.command, source_type: data.source_type, params_id: data.params_id, params_type: data.params_type };
  } else {
    v = data.value;
    const vt = channel.metadata.get("value_type");
    if (v !== null && vt === "double") v = Number(v);
    if (v !== null && vt === "doubles") v = v.map(Number);
  }
  return channel.topic + "\t" + logTime.toString() + "\t" + canon(v);
}

async function main() {
  const args = process.argv.slice(2);
  const file = args[0];
  let expect = null;
  const topics = [];
  for (let i = 1; i < args.length; i++) {
    if (args[i] === "--expect") expect = args[++i];
    else if (args[i] === "--topic") topics.push(args[++i]);
  }
  const fd = fs.openSync(file, "r");
  const size = fs.fstatSync(fd).size;
  const readable = {
    size: async () => BigInt(size),
    read: async (offset, length) => {
      const buf = Buffer.alloc(Number(length));
      fs.readSync(fd, buf, 0, Number(length), Number(offset));
      return new Uint8Array(buf.buffer, buf.byteOffset, buf.byteLength);
    },
  };
  const reader = await McapIndexedReader.Initialize({
    readable,
    decompressHandlers: { zstd: (data, size) => fzstd.decompress(data, new Uint8Array(Number(size))) },
  });
  const problems = [];
  if (!reader.statistics) problems.push("no statistics in the summary");
  const ajv = new Ajv2020({ strict: false, allErrors: false });
  const validators = new Map();
  for (const [id, schema] of reader.schemasById) {
    validators.set(id, ajv.compile(JSON.parse(new TextDecoder().decode(schema.data))));
  }
  const decoder = new TextDecoder();
  const actual = [];
  const seen = new Set();
  let count = 0;
  for await (const message of reader.readMessages({ validateCrcs: true })) {
    const channel = reader.channelsById.get(message.channelId);
    const data = JSON.parse(decoder.decode(message.data));
    const validate = validators.get(channel.schemaId);
    if (!validate(data)) {
      problems.push(`${channel.topic} at ${message.logTime} does not match its schema: ${ajv.errorsText(validate.errors)}`);
    }
    seen.add(channel.topic);
    count++;
    if (channel.metadata.get("kind") !== "scene") actual.push(actualKey(channel, message.logTime, data));
  }
  if (reader.statistics && Number(reader.statistics.messageCount) !== count) {
    problems.push(`statistics say ${reader.statistics.messageCount} messages, the indexed reader read ${count}`);
  }
  if (count > 0 && reader.chunkIndexes.length === 0) problems.push("messages but no chunk index");
  for (const t of topics) if (!seen.has(t)) problems.push("no message on topic " + t);
  if (expect) {
    const expected = fs.readFileSync(expect, "utf8").split("\n").filter((l) => l.trim()).map((l) => expectedKey(JSON.parse(l))).sort();
    actual.sort();
    const same = expected.length === actual.length && expected.every((e, i) => e === actual[i]);
    if (!same) {
      const a = new Set(actual);
      const e = new Set(expected);
      problems.push(`${actual.length} messages vs ${expected.length} database rows; missing ${JSON.stringify(expected.filter((x) => !a.has(x)).slice(0, 3))}; unexpected ${JSON.stringify(actual.filter((x) => !e.has(x)).slice(0, 3))}`);
    }
  }
  if (problems.length > 0) {
    console.log("@mcap/core: FAIL " + problems.slice(0, 5).join("; "));
    process.exit(1);
  }
  console.log(`@mcap/core: OK ${count} messages, ${reader.channelsById.size} channels, ${reader.chunkIndexes.length} chunks, ${reader.attachmentIndexes.length} attachments, ${reader.metadataIndexes.length} metadata, rows ${actual.length}`);
}

main().catch((e) => {
  console.log("@mcap/core: FAIL " + (e && e.message ? e.message : e));
  process.exit(1);
});

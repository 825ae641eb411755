// Foxglove's own WebSocket client (@foxglove/ws-protocol), driven against player-relay's
// Foxglove front by player-relay/tests/foxglove.rs. Each mode prints one JSON object on
// stdout (the Rust test asserts on it) and exits 0, or 1 when what it waited for never came.
//
//   node foxglove_client.mjs observe URL WANT TIMEOUT_MS
//     subscribes to every channel, decodes each message with protobufjs from the schema the
//     server advertised, until WANT holds: {"scans": N, "topics": [...], "children": [...]}
//     (N LaserScans, a message on each topic, a transform to each child frame).
//   node foxglove_client.mjs bad URL TIMEOUT_MS
//     one well-behaved client watches scans while others send garbage text, a garbage binary
//     frame, an oversized frame and a subscription to a channel that does not exist.
//   node foxglove_client.mjs many URL COUNT HOLD_MS TIMEOUT_MS
//     COUNT clients connect at once and each waits for its first scan; prints "CONNECTED"
//     (for the test to measure the server then), holds them HOLD_MS, then the JSON.
//   node foxglove_client.mjs stall URL COUNT HOLD_MS TIMEOUT_MS
//     COUNT clients subscribe to every channel, and once each has a message, stop reading
//     (their socket paused); prints "STALLED", holds them HOLD_MS, then the JSON.
//   node foxglove_client.mjs watch URL PATTERN SECONDS TIMEOUT_MS
//     as a person's layout does: subscribes to the channels whose topic matches the regular
//     expression PATTERN (advertised now or later); once each has had a message prints
//     "WATCHING", counts messages for SECONDS, then unsubscribes, closes, and prints
//     {"channels": N, "messages": M, "hz": {"min": …, "median": …}} (per channel).
//   node foxglove_client.mjs protocols URL TIMEOUT_MS
//     opens sockets offering each subprotocol alone (the spec's, as Lichtblick and
//     FoxgloveClient.SUPPORTED_SUBPROTOCOL name it, and the SDK's), both, and an unrelated
//     one; reports the protocol the server chose and its first message's op, or the refusal.

import wsProtocol from "@foxglove/ws-protocol";
import protobuf from "protobufjs";
import descriptor from "protobufjs/ext/descriptor.js";
import WebSocket from "ws";

// ws-protocol is CommonJS: its named exports come through the default one.
const { FoxgloveClient } = wsProtocol;

const [mode, url, ...args] = process.argv.slice(2);
// The relay accepts both names of the protocol: the spec's "foxglove.websocket.v1" (what
// FoxgloveClient and Lichtblick offer) and the SDK's "foxglove.sdk.v1" (newer Foxglove
// clients); the "protocols" mode checks each. The other modes use the SDK's name, as the
// Foxglove app does.
const PROTOCOL = "foxglove.sdk.v1";

function connect() {
  return new FoxgloveClient({ ws: new WebSocket(url, [PROTOCOL]) });
}

// Prints the one result and exits, once: events still queued before the exit are ignored.
let finished = false;
function finish(result, ok) {
  if (finished) return;
  finished = true;
  process.stdout.write(JSON.stringify(result) + "\n", () => process.exit(ok ? 0 : 1));
}

// A decoder for one advertised channel: its protobuf schema is a FileDescriptorSet, base64.
function decoderFor(channel) {
  if (channel.encoding !== "protobuf") {
    throw new Error(`${channel.topic}: encoding ${channel.encoding}, expected protobuf`);
  }
  const set = descriptor.FileDescriptorSet.decode(Buffer.from(channel.schema, "base64"));
  const type = protobuf.Root.fromDescriptor(set).lookupType(channel.schemaName);
  return (view) => {
    const bytes = new Uint8Array(view.buffer, view.byteOffset, view.byteLength);
    return type.toObject(type.decode(bytes), { longs: Number, defaults: true });
  };
}

function observe(want, timeoutMs) {
  const client = connect();
  const subscriptions = new Map(); // subscription id → { channel, decode }
  const result = { channels: [], counts: {}, scans: [], transforms: [], grids: [], logs: [] };
  const children = new Set();
  const satisfied = () =>
    result.scans.length >= (want.scans ?? 0) &&
    (want.topics ?? []).every((t) => result.counts[t] > 0) &&
    (want.children ?? []).every((c) => children.has(c));
  const timer = setTimeout(() => finish({ ...result, timedOut: true }, false), timeoutMs);
  client.on("error", (e) => result.error = String(e));
  client.on("advertise", (channels) => {
    for (const channel of channels) {
      result.channels.push({ topic: channel.topic, schemaName: channel.schemaName });
      const id = client.subscribe(channel.id);
      subscriptions.set(id, { channel, decode: decoderFor(channel) });
    }
  });
  client.on("message", ({ subscriptionId, timestamp, data }) => {
    const { channel, decode } = subscriptions.get(subscriptionId);
    const message = decode(data);
    result.counts[channel.topic] = (result.counts[channel.topic] ?? 0) + 1;
    const time = message.timestamp ?? {};
    switch (channel.schemaName) {
      case "foxglove.LaserScan":
        result.scans.push({
          topic: channel.topic,
          frame: message.frameId,
          sec: time.seconds,
          nsec: time.nanos,
          logTime: Number(timestamp),
          ranges: message.ranges,
        });
        break;
      case "foxglove.FrameTransform":
        if (!children.has(message.childFrameId)) {
          result.transforms.push({ parent: message.parentFrameId, child: message.childFrameId });
          children.add(message.childFrameId);
        }
        break;
      case "foxglove.Grid":
        result.grids.push({
          topic: channel.topic,
          frame: message.frameId,
          columns: message.columnCount,
          cellSize: message.cellSize,
          rowStride: message.rowStride,
          bytes: message.data.length,
        });
        break;
      case "foxglove.Log":
        result.logs.push(message.message);
        break;
    }
    if (satisfied()) {
      clearTimeout(timer);
      client.close();
      finish(result, true);
    }
  });
}

// Opens a raw WebSocket, sends `payload` once open, and reports the first status the server
// sends back and whether (and how) it closed the connection, within `ms`.
function rawExchange(payload, ms) {
  return new Promise((resolve) => {
    const outcome = { statuses: [], closed: null, error: null };
    const ws = new WebSocket(url, [PROTOCOL], { maxPayload: 0 });
    let finished = false;
    const done = () => {
      if (finished) return;
      finished = true;
      clearTimeout(timer);
      ws.terminate();
      resolve(outcome);
    };
    const timer = setTimeout(done, ms);
    ws.on("open", () => ws.send(payload));
    ws.on("message", (data, isBinary) => {
      if (isBinary) return;
      const message = JSON.parse(data.toString());
      if (message.op === "status") {
        outcome.statuses.push({ level: message.level, message: message.message });
        done();
      }
    });
    ws.on("close", (code, reason) => {
      if (!finished) outcome.closed = { code, reason: reason.toString() };
      done();
    });
    ws.on("error", (e) => { outcome.error = String(e.message ?? e); });
  });
}

async function bad(timeoutMs) {
  // The bystander: subscribed to a scan channel all along.
  const bystander = connect();
  let scans = 0;
  const scanChannel = new Promise((resolve) => {
    bystander.on("advertise", (channels) => {
      const scan = channels.find((c) => c.schemaName === "foxglove.LaserScan");
      if (scan) { bystander.subscribe(scan.id); resolve(scan); }
    });
  });
  bystander.on("message", () => scans += 1);
  const timer = setTimeout(() => finish({ timedOut: true, scans }, false), timeoutMs);
  await scanChannel;
  const patience = 3000;
  const result = {
    garbageText: await rawExchange("this is not JSON {", patience),
    unknownOp: await rawExchange(JSON.stringify({ op: "launchMissiles" }), patience),
    garbageBinary: await rawExchange(Buffer.from([0xff, 0x00, 0x13, 0x37]), patience),
    oversized: await rawExchange(Buffer.alloc(20 * 1024 * 1024, 7), patience),
    unknownChannel: await rawExchange(
      JSON.stringify({ op: "subscribe", subscriptions: [{ id: 1, channelId: 987654 }] }),
      patience,
    ),
  };
  result.scansBefore = scans;
  // The bystander still gets scans, and a newcomer is still served.
  while (scans < result.scansBefore + 3) await new Promise((r) => setTimeout(r, 50));
  const newcomer = connect();
  await new Promise((resolve) => newcomer.on("advertise", resolve));
  newcomer.close();
  result.scansAfter = scans;
  clearTimeout(timer);
  bystander.close();
  finish(result, true);
}

async function many(count, holdMs, timeoutMs) {
  const started = Date.now();
  const timer = setTimeout(() => finish({ timedOut: true, ...tally() }, false), timeoutMs);
  const clients = [];
  const states = [];
  const tally = () => ({
    connected: states.filter((s) => s.open).length,
    advertised: states.filter((s) => s.advertised).length,
    scanned: states.filter((s) => s.scanned).length,
    errors: states.filter((s) => s.error).length,
  });
  const firstScans = [];
  for (let i = 0; i < count; i++) {
    const client = connect();
    const state = { open: false, advertised: false, scanned: false, error: null };
    clients.push(client);
    states.push(state);
    firstScans.push(new Promise((resolve) => {
      client.on("open", () => state.open = true);
      client.on("error", (e) => state.error = String(e));
      client.on("advertise", (channels) => {
        state.advertised = true;
        const scan = channels.find((c) => c.schemaName === "foxglove.LaserScan");
        if (scan) client.subscribe(scan.id);
      });
      client.on("message", () => { if (!state.scanned) { state.scanned = true; resolve(); } });
    }));
  }
  await Promise.all(firstScans);
  const elapsedMs = Date.now() - started;
  process.stdout.write("CONNECTED\n");
  await new Promise((r) => setTimeout(r, holdMs));
  clearTimeout(timer);
  for (const client of clients) client.close();
  finish({ count, elapsedMs, ...tally() }, true);
}

async function stall(count, holdMs, timeoutMs) {
  const timer = setTimeout(() => finish({ timedOut: true }, false), timeoutMs);
  const sockets = [];
  const stalled = [];
  for (let i = 0; i < count; i++) {
    const ws = new WebSocket(url, [PROTOCOL]);
    const client = new FoxgloveClient({ ws });
    sockets.push(ws);
    stalled.push(new Promise((resolve) => {
      client.on("advertise", (channels) => channels.forEach((c) => client.subscribe(c.id)));
      client.on("message", () => { ws.pause(); resolve(); });
    }));
  }
  await Promise.all(stalled);
  process.stdout.write("STALLED\n");
  await new Promise((r) => setTimeout(r, holdMs));
  clearTimeout(timer);
  const open = sockets.filter((ws) => ws.readyState === WebSocket.OPEN).length;
  for (const ws of sockets) ws.terminate();
  finish({ count, open }, true);
}

// One socket offering `offered`: what the server chose and its first message, or how the
// connection failed.
function handshake(offered, ms) {
  return new Promise((resolve) => {
    const outcome = { offered, protocol: null, firstOp: null, refused: null };
    const ws = new WebSocket(url, offered);
    const done = () => { clearTimeout(timer); ws.terminate(); resolve(outcome); };
    const timer = setTimeout(done, ms);
    ws.on("open", () => outcome.protocol = ws.protocol);
    ws.on("message", (data, isBinary) => {
      if (!isBinary) outcome.firstOp ??= JSON.parse(data.toString()).op;
      done();
    });
    ws.on("unexpected-response", (_request, response) => {
      outcome.refused = response.statusCode;
      done();
    });
    ws.on("error", (e) => { outcome.refused ??= String(e.message ?? e); done(); });
  });
}

async function protocols(timeoutMs) {
  const timer = setTimeout(() => finish({ timedOut: true }, false), timeoutMs);
  const result = {
    spec: await handshake([FoxgloveClient.SUPPORTED_SUBPROTOCOL], 3000),
    sdk: await handshake(["foxglove.sdk.v1"], 3000),
    both: await handshake(["foxglove.websocket.v1", "foxglove.sdk.v1"], 3000),
    other: await handshake(["chat"], 3000),
  };
  clearTimeout(timer);
  finish(result, true);
}

function watch(pattern, seconds, timeoutMs) {
  const client = connect();
  const wanted = new RegExp(pattern);
  const topics = new Map(); // subscription id → topic
  const counts = new Map(); // topic → messages while counting
  let counting = false;
  const timer = setTimeout(() => finish({ timedOut: true, channels: topics.size }, false), timeoutMs);
  client.on("error", (e) => console.error(String(e)));
  client.on("advertise", (channels) => {
    for (const channel of channels) {
      if (wanted.test(channel.topic)) topics.set(client.subscribe(channel.id), channel.topic);
    }
  });
  client.on("message", ({ subscriptionId }) => {
    const topic = topics.get(subscriptionId);
    counts.set(topic, (counts.get(topic) ?? 0) + (counting ? 1 : 0));
    if (counting || counts.size < topics.size) return;
    counting = true;
    clearTimeout(timer);
    for (const topic of counts.keys()) counts.set(topic, 0);
    console.log("WATCHING");
    setTimeout(() => {
      for (const id of topics.keys()) client.unsubscribe(id);
      client.close();
      const hz = [...counts.values()].map((n) => n / seconds).sort((a, b) => a - b);
      const messages = hz.reduce((a, b) => a + b, 0) * seconds;
      finish({
        channels: topics.size,
        messages,
        hz: { min: hz[0] ?? 0, median: hz[Math.floor(hz.length / 2)] ?? 0 },
      }, true);
    }, seconds * 1000);
  });
}

switch (mode) {
  case "watch":
    watch(args[0], Number(args[1]), Number(args[2]));
    break;
  case "protocols":
    protocols(Number(args[0]));
    break;
  case "observe":
    observe(JSON.parse(args[0]), Number(args[1]));
    break;
  case "bad":
    bad(Number(args[0]));
    break;
  case "many":
    many(Number(args[0]), Number(args[1]), Number(args[2]));
    break;
  case "stall":
    stall(Number(args[0]), Number(args[1]), Number(args[2]));
    break;
  default:
    console.error(`unknown mode ${mode}`);
    process.exit(2);
}

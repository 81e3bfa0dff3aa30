// A third-party Foxglove client for the test suite: Foxglove's own @foxglove/ws-protocol
// client, @foxglove/rosmsg to read the advertised schemas, @foxglove/rosmsg2-serialization
// to decode and encode CDR. It connects to argv[2] and runs the steps given as JSON in
// argv[3], printing one JSON line per result; argv[4], when given, is the subprotocols it
// offers, comma-separated (by default the SDK's name and the protocol's old one, as the app).
//   {"do": "channels"}                                     the advertised channels
//   {"do": "echo", "topic": T, "count": N}                 N decoded messages of T
//   {"do": "rate", "topic": T, "seconds": S}               messages of T received in S seconds
//   {"do": "watchall", "seconds": S}                       every channel subscribed for S seconds
//   {"do": "stall", "topic": T, "seconds": S}              subscribed, but not reading for S seconds
//   {"do": "publish", "topic": T, "type": "pkg/msg/X", "message": {...}, "hz": H, "seconds": S}
//   {"do": "call", "service": S, "request": {...}}         a service's decoded response
//   {"do": "asset", "uri": U}                              a fetchAsset's status and size
//   {"do": "parameters", "names": [...]}                   getParameters
//   {"do": "paramwatch", "names": [...], "seconds": S}     parameter updates for S seconds
//   {"do": "graph"}                                        the connection graph
//   {"do": "time", "seconds": S}                           the server's time messages
//   {"do": "abuse", "what": "subscribe10000"|"unadvertised"|"oversized"|"mismatched"|"garbage"}
//   {"do": "wait", "seconds": S}
//   {"do": "wait_closed", "seconds": S}                    until the server closes, at most S s
const WebSocket = require("ws");
const { FoxgloveClient } = require("@foxglove/ws-protocol");
const { parse } = require("@foxglove/rosmsg");
const { MessageReader, MessageWriter } = require("@foxglove/rosmsg2-serialization");

const url = process.argv[2];
const steps = JSON.parse(process.argv[3] || "[]");
const say = (what) => console.log(JSON.stringify(what, (k, v) => (typeof v === "bigint" ? Number(v) : v)));
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// the Foxglove SDK speaks the protocol as "foxglove.sdk.v1" (the app offers both names)
const protocols = process.argv[4] ? process.argv[4].split(",") : ["foxglove.sdk.v1", FoxgloveClient.SUPPORTED_SUBPROTOCOL];
const ws = new WebSocket(url, protocols, { maxPayload: 1 << 30 });
ws.on("unexpected-response", (req, res) => {
  say({ refused: res.statusCode });
  process.exit(3);
});
ws.on("error", (error) => {
  say({ error: String(error.message || error) });
  process.exit(4);
});
const client = new FoxgloveClient({ ws });
const channels = new Map();
const services = new Map();
const waiting = { message: [], serviceCallResponse: [], fetchAssetResponse: [], parameterValues: [], connectionGraphUpdate: [], time: [], serviceCallFailure: [] };
let info = null;
client.on("serverInfo", (i) => { info = i; });
client.on("advertise", (list) => list.forEach((c) => channels.set(c.topic, c)));
client.on("unadvertise", (ids) => ids.forEach((id) => { for (const [t, c] of channels) if (c.id === id) channels.delete(t); }));
client.on("advertiseServices", (list) => list.forEach((s) => services.set(s.name, s)));
client.on("status", (s) => say({ status: s.message, level: s.level }));
let closing = false;
let closed = false;
ws.on("close", (code, reason) => { closed = true; if (!closing) say({ closed: code, reason: String(reason) }); });
for (const name of Object.keys(waiting)) client.on(name, (e) => waiting[name].forEach((f) => f(e)));

const until = async (check, seconds) => {
  const end = Date.now() + seconds * 1000;
  while (Date.now() < end) { const v = check(); if (v) return v; await sleep(20); }
  return null;
};
const reader = (schemaName, schema) => new MessageReader(parse(schema, { ros2: true }));
const writer = (schema) => new MessageWriter(parse(schema, { ros2: true }));
const once = (name, test, seconds) => new Promise((resolve) => {
  const f = (e) => { if (test(e)) { waiting[name] = waiting[name].filter((g) => g !== f); resolve(e); } };
  waiting[name].push(f);
  setTimeout(() => { waiting[name] = waiting[name].filter((g) => g !== f); resolve(null); }, seconds * 1000);
});

async function run() {
  await until(() => info, 10);
  say({ connected: info && info.name, capabilities: info && info.capabilities, protocol: ws.protocol });
  for (const step of steps) {
    if (step.do === "wait") await sleep(step.seconds * 1000);
    else if (step.do === "wait_closed") await until(() => closed, step.seconds);
    else if (step.do === "channels") {
      await until(() => channels.size > 0, 10);
      if (step.topic) await until(() => channels.get(step.topic), 15);
      say({ channels: [...channels.values()].map((c) => ({ topic: c.topic, encoding: c.encoding, schemaName: c.schemaName, schemaEncoding: c.schemaEncoding, schema: c.schema })) });
    } else if (step.do === "echo" || step.do === "rate") {
      const channel = await until(() => channels.get(step.topic), 15);
      if (!channel) { say({ missing: step.topic }); continue; }
      const read = reader(channel.schemaName, channel.schema);
      const got = [];
      let count = 0;
      const f = (e) => { if (e.subscriptionId === sub) { count += 1; if (step.do === "echo" && got.length < step.count) got.push(read.readMessage(e.data)); } };
      waiting.message.push(f);
      const sub = client.subscribe(channel.id);
      const start = Date.now();
      if (step.do === "echo") await until(() => got.length >= step.count, step.seconds || 20);
      else { await sleep(step.seconds * 1000); }
      client.unsubscribe(sub);
      waiting.message = waiting.message.filter((g) => g !== f);
      if (step.do === "echo") say({ echo: step.topic, messages: got });
      else say({ rate: step.topic, count, seconds: (Date.now() - start) / 1000 });
    } else if (step.do === "stall") {
      // subscribe, then stop reading the socket for S seconds (a slow client), then read on
      const channel = await until(() => channels.get(step.topic), 15);
      if (!channel) { say({ missing: step.topic }); continue; }
      let count = 0;
      const f = () => { count += 1; };
      waiting.message.push(f);
      client.subscribe(channel.id);
      await sleep(500);
      ws.pause();
      const before = count;
      await sleep(step.seconds * 1000);
      ws.resume();
      await sleep(3000);
      waiting.message = waiting.message.filter((g) => g !== f);
      say({ stalled: step.topic, before, after: count - before, seconds: step.seconds });
    } else if (step.do === "watchall") {
      await until(() => channels.size > 0, 15);
      let count = 0;
      const f = () => { count += 1; };
      waiting.message.push(f);
      const subs = [...channels.values()].map((c) => client.subscribe(c.id));
      await sleep(step.seconds * 1000);
      subs.forEach((id) => client.unsubscribe(id));
      waiting.message = waiting.message.filter((g) => g !== f);
      say({ watched: subs.length, count });
    } else if (step.do === "publish") {
      const channel = { topic: step.topic, encoding: "cdr", schemaName: step.type };
      const id = client.advertise(channel);
      const definition = step.schema || null;
      const bytes = definition ? writer(definition).writeMessage(step.message) : new Uint8Array(step.raw || []);
      const end = Date.now() + (step.seconds || 1) * 1000;
      let sent = 0;
      while (Date.now() < end) { client.sendMessage(id, bytes); sent += 1; await sleep(1000 / (step.hz || 10)); }
      client.unadvertise(id);
      say({ published: step.topic, sent });
    } else if (step.do === "call") {
      const service = await until(() => services.get(step.service), 15);
      if (!service) { say({ missing: step.service }); continue; }
      const request = service.request || { schema: service.requestSchema };
      const response = service.response || { schema: service.responseSchema };
      const callId = Math.floor(Math.random() * 1e9);
      const bytes = step.raw ? new Uint8Array(step.raw) : writer(request.schema).writeMessage(step.request);
      const answer = Promise.race([
        once("serviceCallResponse", (e) => e.callId === callId, step.seconds || 15).then((e) => e && { ok: e }),
        once("serviceCallFailure", (e) => e.callId === callId, step.seconds || 15).then((e) => e && { failed: e }),
      ]);
      client.sendServiceCallRequest({ serviceId: service.id, callId, encoding: "cdr", data: new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength) });
      const got = await answer;
      if (got && got.ok) say({ called: step.service, response: reader(null, response.schema).readMessage(got.ok.data) });
      else say({ called: step.service, failed: got && got.failed ? got.failed.message : "no answer" });
    } else if (step.do === "asset") {
      const requestId = Math.floor(Math.random() * 1e9);
      const answer = once("fetchAssetResponse", (e) => e.requestId === requestId, 10);
      client.fetchAsset(step.uri, requestId);
      const got = await answer;
      say({ asset: step.uri, status: got ? got.status : "none", size: got && got.data ? got.data.byteLength : 0, error: got && got.error });
    } else if (step.do === "parameters") {
      const answer = once("parameterValues", () => true, 15);
      client.getParameters(step.names || [], "p1");
      const got = await answer;
      say({ parameters: got ? got.parameters : null });
    } else if (step.do === "paramwatch") {
      const seen = [];
      const f = (e) => seen.push(...e.parameters);
      waiting.parameterValues.push(f);
      client.subscribeParameterUpdates(step.names);
      await sleep(step.seconds * 1000);
      client.unsubscribeParameterUpdates(step.names);
      waiting.parameterValues = waiting.parameterValues.filter((g) => g !== f);
      say({ parameterUpdates: seen });
    } else if (step.do === "graph") {
      const answer = once("connectionGraphUpdate", (e) => (e.publishedTopics || []).length > 0, 10);
      client.subscribeConnectionGraph();
      const got = await answer;
      say({ graph: got });
    } else if (step.do === "time") {
      const seen = [];
      const f = (e) => seen.push(Number(e.timestamp));
      waiting.time.push(f);
      await sleep(step.seconds * 1000);
      say({ times: seen });
    } else if (step.do === "abuse") {
      if (step.what === "subscribe10000") {
        for (let i = 0; i < 10000; i++) ws.send(JSON.stringify({ op: "subscribe", subscriptions: [{ id: 100000 + i, channelId: 900000 + i }] }));
      } else if (step.what === "unadvertised") {
        const frame = new Uint8Array(5 + 16); frame[0] = 1; new DataView(frame.buffer).setUint32(1, 4242, true); ws.send(frame);
      } else if (step.what === "oversized") {
        ws.send(new Uint8Array(step.bytes || 64 * 1024 * 1024));
      } else if (step.what === "garbage") {
        ws.send("{ this is not json");
      }
      say({ abused: step.what });
    }
  }
  closing = true;
  client.close();
  await sleep(100);
  process.exit(0);
}
client.on("open", () => run().catch((e) => { say({ error: String(e && e.stack || e) }); process.exit(5); }));
setTimeout(() => { say({ error: "timed out" }); process.exit(6); }, 120000);

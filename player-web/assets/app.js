// The relay's web page: a live top view of every robot and a row per robot. Messages arrive
// as JSON on one WebSocket, in player-proto's own types ({"Laser":{"Scan":{...}}}); the page
// keeps the newest of each and redraws at most once per animation frame.
"use strict";

const canvas = document.getElementById("view");
const ctx = canvas.getContext("2d");
const robots = new Map(); // the robot's name (else "host:port") -> robot
let controller = false;
let selected = null; // { robot, index }
let socket = null;
const view = { x: 0, y: 0, zoom: 40, userMoved: false };
let dirty = true;

function robotOf(name) {
  if (!robots.has(name)) {
    robots.set(name, { link: { state: "connecting" }, devices: new Map(), maps: new Map(), rows: [] });
  }
  return robots.get(name);
}

function deviceOf(robot, device) {
  if (!robot.devices.has(device)) robot.devices.set(device, {});
  return robot.devices.get(device);
}

// ---- messages -------------------------------------------------------------------------

function onMessage(m) {
  switch (m.type) {
    case "hello":
      controller = m.controller;
      setRole(m.rule);
      break;
    case "robot": {
      const robot = robotOf(m.robot);
      robot.link = m.link;
      if (m.link.state === "connected") { robot.devices.clear(); robot.maps.clear(); }
      break;
    }
    case "message":
      onPlayer(robotOf(m.robot), m);
      break;
    case "world":
      setWalls(m.walls);
      break;
    case "status":
      showRows(m.rows);
      break;
    case "refused":
      document.getElementById("refused").textContent = m.why;
      break;
  }
  dirty = true;
}

// One body: {"Interface":{"Variant":value}}.
function unwrap(body) {
  const iface = Object.keys(body)[0];
  const variant = Object.keys(body[iface])[0];
  return [iface, variant, body[iface][variant]];
}

function onPlayer(robot, m) {
  const [iface, variant, value] = unwrap(m.body);
  const d = deviceOf(robot, m.device);
  if (iface === "Map") {
    if (variant === "Info" || variant === "InfoData") startMap(robot, m.device, value);
    else if (variant === "Tile") paintTile(robot, m.device, value);
    return;
  }
  if (variant === "Geometry" || variant === "GeometryData") d.geom = value;
  else if (variant === "Config") d.config = value;
  else d[variant] = value;
}

// ---- the map: tiles arrive zlib-compressed, one signed byte per cell ---------------------

function startMap(robot, device, info) {
  if (!(info.width > 0 && info.height > 0 && info.width * info.height <= 8192 * 8192)) return;
  const grid = document.createElement("canvas");
  grid.width = info.width;
  grid.height = info.height;
  const g = grid.getContext("2d");
  g.fillStyle = "rgb(150,150,150)";
  g.fillRect(0, 0, info.width, info.height);
  robot.maps.set(device, { info, grid });
}

async function paintTile(robot, device, tile) {
  const map = robot.maps.get(device);
  if (!map || tile.width === 0 || tile.height === 0) return;
  const packed = Uint8Array.from(atob(tile.data), (c) => c.charCodeAt(0));
  let cells;
  try {
    const stream = new Blob([packed]).stream().pipeThrough(new DecompressionStream("deflate"));
    cells = new Int8Array(await new Response(stream).arrayBuffer());
  } catch (e) {
    console.warn("map tile at", tile.col, tile.row, "did not inflate:", e);
    return;
  }
  if (cells.length !== tile.width * tile.height) return;
  const image = new ImageData(tile.width, tile.height);
  for (let i = 0; i < cells.length; i++) {
    const grey = cells[i] < 0 ? 235 : cells[i] > 0 ? 25 : 150;
    image.data.set([grey, grey, grey, 255], i * 4);
  }
  map.grid.getContext("2d").putImageData(image, tile.col, tile.row);
  dirty = true;
}

// ---- geometry -------------------------------------------------------------------------

function compose(a, b) {
  const c = Math.cos(a.a), s = Math.sin(a.a);
  return { x: a.x + c * b.x - s * b.y, y: a.y + s * b.x + c * b.y, a: a.a + b.a };
}
const pose2 = (p) => ({ x: p.px, y: p.py, a: p.pa });
const mount = (g) => (g && g.pose ? { x: g.pose.px, y: g.pose.py, a: g.pose.pyaw } : { x: 0, y: 0, a: 0 });

// The base a device rides on: the position2d of its index, else index 0's.
function baseOf(robot, index) {
  const own = robot.devices.get(`position2d:${index}`);
  const base = own && own.State ? own : robot.devices.get("position2d:0");
  return base && base.State ? pose2(base.State.pos) : null;
}

function bases(robot) {
  const out = [];
  for (const [name, d] of robot.devices) {
    if (name.startsWith("position2d:") && d.State) out.push({ index: +name.split(":")[1], d });
  }
  return out;
}

// ---- drawing --------------------------------------------------------------------------

// Robots in name order, each a golden angle round the colour wheel from the last.
function colourOf(name) {
  const order = [...robots.keys()].sort().indexOf(name);
  return `hsl(${(order * 137.5 + 200) % 360},65%,42%)`;
}

function toScreen(x, y) {
  return [canvas.width / 2 + (x - view.x) * view.zoom, canvas.height / 2 - (y - view.y) * view.zoom];
}
function toWorld(sx, sy) {
  return [view.x + (sx - canvas.width / 2) / view.zoom, view.y - (sy - canvas.height / 2) / view.zoom];
}

function worldTransform() {
  ctx.setTransform(view.zoom, 0, 0, -view.zoom, canvas.width / 2 - view.x * view.zoom, canvas.height / 2 + view.y * view.zoom);
}

// The robots' data comes at about 10 Hz: drawing more often than this redraws the same
// poses, and at a thousand robots costs the watching machine more than the relay.
const DRAW_EVERY_MS = 50;
let drawnAt = -Infinity;

function draw(now) {
  requestAnimationFrame(draw);
  const ratio = window.devicePixelRatio || 1;
  const w = Math.round(canvas.clientWidth * ratio), h = Math.round(canvas.clientHeight * ratio);
  if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; dirty = true; }
  if (!dirty || now - drawnAt < DRAW_EVERY_MS) return;
  drawnAt = now;
  dirty = false;
  if (!view.userMoved) frame();
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  worldTransform();
  ctx.imageSmoothingEnabled = false;
  drawWalls();
  for (const robot of robots.values()) {
    for (const { info, grid } of robot.maps.values()) {
      ctx.save();
      ctx.translate(info.origin.px, info.origin.py);
      ctx.drawImage(grid, 0, 0, info.width * info.scale, info.height * info.scale);
      ctx.restore();
    }
  }
  drawGrid();
  for (const [name, robot] of robots) drawRobot(name, robot);
  drawLabels();
}

function drawGrid() {
  const [x0, y1] = toWorld(0, 0), [x1, y0] = toWorld(canvas.width, canvas.height);
  const step = view.zoom > 20 ? 1 : view.zoom > 4 ? 5 : 25;
  ctx.lineWidth = 1 / view.zoom;
  ctx.strokeStyle = "rgba(0,0,0,0.07)";
  ctx.beginPath();
  for (let x = Math.floor(x0 / step) * step; x <= x1; x += step) { ctx.moveTo(x, y0); ctx.lineTo(x, y1); }
  for (let y = Math.floor(y0 / step) * step; y <= y1; y += step) { ctx.moveTo(x0, y); ctx.lineTo(x1, y); }
  ctx.stroke();
}

// The view frames the maps and walls when there are any, else every robot, until someone
// moves it.
function frame() {
  let box = null;
  const grow = (x, y) => {
    box = box ? [Math.min(box[0], x), Math.min(box[1], y), Math.max(box[2], x), Math.max(box[3], y)] : [x, y, x, y];
  };
  for (const robot of robots.values()) {
    for (const { info } of robot.maps.values()) {
      grow(info.origin.px, info.origin.py);
      grow(info.origin.px + info.width * info.scale, info.origin.py + info.height * info.scale);
    }
  }
  growByWalls(grow);
  const mapBox = box;
  if (!box) for (const robot of robots.values()) for (const { d } of bases(robot)) grow(d.State.pos.px, d.State.pos.py);
  if (!box || canvas.width === 0) return;
  // Robots alone are framed with room for what their sensors reach (a map frames itself);
  // a lone robot gets 10 m around it rather than filling the view.
  const margin = box === mapBox ? 1 : 3, least = 10;
  const w = Math.max(box[2] - box[0] + 2 * margin, least), h = Math.max(box[3] - box[1] + 2 * margin, least);
  view.x = (box[0] + box[2]) / 2;
  view.y = (box[1] + box[3]) / 2;
  view.zoom = Math.min(canvas.width / w, canvas.height / h, 200);
}

function setRole(rule) {
  const role = document.getElementById("role");
  role.textContent = controller ? "controller" : "observing";
  role.className = "badge" + (controller ? " control" : "");
  const said = rule.charAt(0).toUpperCase() + rule.slice(1);
  document.getElementById("hint").textContent = controller
    ? `${said}. Click a robot, then click where it should go, or drive it with the arrow keys.`
    : `${said}. This page watches.`;
}

// ---- input ----------------------------------------------------------------------------

function select(robot, index) {
  const changed = !selected || selected.robot !== robot;
  selected = { robot, index };
  dirty = true;
  if (changed) showRows(lastRows); // the selected robot's row comes first
  for (const tr of document.querySelectorAll("#rows tr[data-robot]")) {
    tr.classList.toggle("selected", tr.dataset.robot === robot);
  }
}

function send(command) {
  if (!controller || !socket || socket.readyState !== WebSocket.OPEN) return;
  socket.send(JSON.stringify(command));
}

function robotAt(x, y) {
  let best = null;
  for (const [name, robot] of robots) {
    for (const { index, d } of bases(robot)) {
      const dist = Math.hypot(d.State.pos.px - x, d.State.pos.py - y);
      if (dist < 0.6 && (!best || dist < best.dist)) best = { name, index, dist };
    }
  }
  return best;
}

const pointers = new Map();
let dragged = false;
canvas.addEventListener("pointerdown", (e) => {
  canvas.setPointerCapture(e.pointerId);
  pointers.set(e.pointerId, { x: e.offsetX, y: e.offsetY });
  dragged = false;
});
canvas.addEventListener("pointermove", (e) => {
  const last = pointers.get(e.pointerId);
  if (!last) return;
  const ratio = window.devicePixelRatio || 1;
  const dx = e.offsetX - last.x, dy = e.offsetY - last.y;
  if (pointers.size === 2) {
    const [a, b] = [...pointers.values()];
    const before = Math.hypot(a.x - b.x, a.y - b.y);
    last.x = e.offsetX; last.y = e.offsetY;
    const after = Math.hypot(a.x - b.x, a.y - b.y);
    if (before > 0) zoomBy(after / before);
  } else {
    if (Math.abs(dx) + Math.abs(dy) > 3) dragged = true;
    if (dragged) {
      view.x -= (dx * ratio) / view.zoom;
      view.y += (dy * ratio) / view.zoom;
      view.userMoved = true;
      dirty = true;
    }
    last.x = e.offsetX; last.y = e.offsetY;
  }
});
canvas.addEventListener("pointerup", (e) => {
  pointers.delete(e.pointerId);
  if (dragged) return;
  const ratio = window.devicePixelRatio || 1;
  const [x, y] = toWorld(e.offsetX * ratio, e.offsetY * ratio);
  const hit = robotAt(x, y);
  if (hit) select(hit.name, hit.index);
  else if (selected) send({ type: "goal", robot: selected.robot, device: `position2d:${selected.index}`, goal: { px: x, py: y, pa: 0 } });
});
canvas.addEventListener("wheel", (e) => { e.preventDefault(); zoomBy(Math.exp(-e.deltaY / 500)); }, { passive: false });
function zoomBy(factor) {
  view.zoom = Math.min(2000, Math.max(0.5, view.zoom * factor));
  view.userMoved = true;
  dirty = true;
}
document.getElementById("fit").addEventListener("click", () => { view.userMoved = false; dirty = true; });

// Arrow keys: a velocity repeated every 100 ms while held (the server stops the base when the
// repeats stop), zero when released, when the tab loses focus or the socket drops.
const held = new Set();
const KEYS = ["ArrowUp", "ArrowDown", "ArrowLeft", "ArrowRight"];
function velocity() {
  const vx = (held.has("ArrowUp") ? 0.5 : 0) - (held.has("ArrowDown") ? 0.5 : 0);
  const va = (held.has("ArrowLeft") ? 0.8 : 0) - (held.has("ArrowRight") ? 0.8 : 0);
  return { vel: { px: vx, py: 0, pa: va }, state: 1 };
}
function drive() {
  if (!selected) return;
  send({ type: "velocity", robot: selected.robot, device: `position2d:${selected.index}`, command: velocity() });
}
function stopDriving() {
  if (held.size === 0) return;
  held.clear();
  drive();
}
window.addEventListener("keydown", (e) => {
  if (!KEYS.includes(e.key)) return;
  e.preventDefault();
  held.add(e.key);
  drive();
});
window.addEventListener("keyup", (e) => {
  if (!KEYS.includes(e.key)) return;
  held.delete(e.key);
  drive();
});
setInterval(() => { if (held.size) drive(); }, 100);
window.addEventListener("blur", stopDriving);
document.addEventListener("visibilitychange", () => { if (document.hidden) stopDriving(); });

// ---- the socket -----------------------------------------------------------------------

function connect() {
  const badge = document.getElementById("socket");
  socket = new WebSocket(`${location.protocol === "https:" ? "wss" : "ws"}://${location.host}/ws`);
  socket.onopen = () => { badge.textContent = "live"; badge.className = "badge ok"; shownSaid = null; };
  socket.onmessage = (e) => onMessage(JSON.parse(e.data));
  socket.onclose = () => {
    held.clear();
    badge.textContent = "reconnecting…";
    badge.className = "badge bad";
    setTimeout(connect, 1000);
  };
}

// For tests and for the curious: the page's state, and where a robot is on the screen.
window.playerWeb = {
  robots,
  view,
  labels,
  get walls() { return walls; },
  get rows() { return lastRows; },
  get selected() { return selected; },
  get controller() { return controller; },
  screenOf(robot, index) {
    const r = robots.get(robot);
    const d = r && r.devices.get(`position2d:${index}`);
    if (!d || !d.State) return null;
    const ratio = window.devicePixelRatio || 1;
    const [sx, sy] = toScreen(d.State.pos.px, d.State.pos.py);
    return [sx / ratio, sy / ratio];
  },
  worldToCss(x, y) {
    const ratio = window.devicePixelRatio || 1;
    const [sx, sy] = toScreen(x, y);
    return [sx / ratio, sy / ratio];
  },
};

connect();
requestAnimationFrame(draw);

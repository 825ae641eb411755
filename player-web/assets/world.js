// What the page draws of the world rather than of one robot: the world's walls, sent once
// when the relay knows them (a world it simulates), and each robot's name beside its body.
// Loaded before app.js, whose drawing state (ctx, view, robots) these use.
"use strict";

let walls = null; // { rects: [[x0, y0, x1, y1]], polygons: [[[x, y], ...]] }, metres
const labels = []; // the names drawn last frame: { name, x, y } in CSS pixels

function setWalls(w) {
  walls = w;
}

// Lets `grow(x, y)` take in every wall, so that the view frames the world.
function growByWalls(grow) {
  if (!walls) return;
  for (const [x0, y0, x1, y1] of walls.rects) { grow(x0, y0); grow(x1, y1); }
  for (const corners of walls.polygons) for (const [x, y] of corners) grow(x, y);
}

function drawWalls() {
  if (!walls) return;
  ctx.fillStyle = "#55595f";
  for (const [x0, y0, x1, y1] of walls.rects) ctx.fillRect(x0, y0, x1 - x0, y1 - y0);
  ctx.fillStyle = "#8a8f96";
  for (const corners of walls.polygons) {
    ctx.beginPath();
    corners.forEach(([x, y], i) => (i === 0 ? ctx.moveTo(x, y) : ctx.lineTo(x, y)));
    ctx.closePath();
    ctx.fill();
  }
}

// Each robot's name beside its body, in screen pixels, when there is room for names: few
// robots, or zoomed in close enough that they do not cover one another.
function drawLabels() {
  labels.length = 0;
  if (robots.size > 64 && view.zoom < 30) return;
  const ratio = window.devicePixelRatio || 1;
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.font = `${12 * ratio}px sans-serif`;
  ctx.textBaseline = "bottom";
  ctx.lineWidth = 3 * ratio;
  ctx.strokeStyle = "rgba(255,255,255,0.85)";
  for (const [name, robot] of robots) {
    for (const { index, d } of bases(robot)) {
      const text = index === 0 ? name : `${name} #${index}`;
      const [sx, sy] = toScreen(d.State.pos.px, d.State.pos.py);
      const x = sx + 0.4 * view.zoom, y = sy - 0.4 * view.zoom;
      ctx.fillStyle = colourOf(name);
      ctx.strokeText(text, x, y);
      ctx.fillText(text, x, y);
      labels.push({ name: text, x: x / ratio, y: y / ratio });
    }
  }
}

// Which robots' sensors the page asks the relay for: those in view. Loaded before app.js, whose
// view, socket and selection these read when the timer fires.
"use strict";

// ---- what the page shows --------------------------------------------------------------

// The relay sends every robot's pose, and the sensors of the robots in view only (of at most
// SENSORS_IN_VIEW robots: zoomed out over more, a scan is a few pixels wide and the page draws
// bodies only). The page says which robots are in view when that changes, at most twice a
// second; what the relay does not send, the robots' servers do not compute.
const SENSORS_IN_VIEW = 64;
let shownSaid = null;

function inView() {
  const [x0, y1] = toWorld(0, 0), [x1, y0] = toWorld(canvas.width, canvas.height);
  const margin = 2; // a robot just outside still reaches in with its scan
  const names = [];
  for (const [name, robot] of robots) {
    const seen = bases(robot).some(({ d }) => {
      const { px, py } = d.State.pos;
      return px >= x0 - margin && px <= x1 + margin && py >= y0 - margin && py <= y1 + margin;
    });
    if (seen) names.push(name);
  }
  return names;
}

function sayShown() {
  if (!socket || socket.readyState !== WebSocket.OPEN || canvas.width === 0) return;
  let names = inView();
  if (names.length > SENSORS_IN_VIEW) names = [];
  if (selected && !names.includes(selected.robot)) names.push(selected.robot);
  names.sort();
  const said = names.join("\n");
  if (said === shownSaid) return;
  shownSaid = said;
  socket.send(JSON.stringify({ type: "show", robots: names }));
  // The sensors of robots out of view stop coming: their last readings are not drawn stale.
  const shown = new Set(names);
  for (const [name, robot] of robots) {
    if (shown.has(name)) continue;
    for (const [device, d] of robot.devices) {
      if (device.startsWith("position2d:")) continue;
      for (const key of Object.keys(d)) if (key !== "geom" && key !== "config") delete d[key];
    }
  }
  dirty = true;
}
setInterval(sayShown, 500);

// How the page draws one robot: its body, its name, and its sensors' readings (laser and
// ranger fans, sonar beams, fiducials, blobs, a planner's path). Loaded before app.js, whose
// drawing state (ctx, view, robots) and helpers (colourOf, bases) these use when called.
"use strict";

function drawRobot(name, robot) {
  const colour = colourOf(name);
  const stale = robot.link.state !== "connected";
  ctx.globalAlpha = stale ? 0.35 : 1;
  const px = 1 / view.zoom;
  for (const [device, d] of robot.devices) {
    const [iface, idx] = device.split(":");
    const base = baseOf(robot, +idx);
    if (!base) continue;
    const sensor = compose(base, mount(d.geom));
    if (iface === "laser" && d.Scan) {
      const s = d.Scan;
      rays(sensor, s.ranges.map((r, i) => [s.min_angle + i * s.resolution, r]), s.max_range, colour);
    } else if (iface === "ranger" && d.Ranges) {
      const r = d.Ranges.ranges, c = d.config;
      const poses = d.geom && d.geom.element_poses;
      if (poses && poses.length === r.length && r.length > 1) {
        const max = c ? c.max_range : Infinity;
        r.forEach((range, i) => { if (range < max) beam(compose(base, mount({ pose: poses[i] })), range, colour); });
      } else if (c) {
        rays(sensor, r.map((range, i) => [c.min_angle + i * c.angular_res, range]), c.max_range, colour);
      }
    } else if (iface === "sonar" && d.Ranges && d.geom) {
      d.Ranges.ranges.forEach((range, i) => {
        if (d.geom.poses[i]) beam(compose(base, mount({ pose: d.geom.poses[i] })), range, colour);
      });
    } else if (iface === "fiducial" && d.Scan) {
      for (const f of d.Scan.fiducials) {
        const at = compose(sensor, { x: f.pose.px, y: f.pose.py, a: 0 });
        ctx.strokeStyle = colour;
        ctx.lineWidth = 2 * px;
        ctx.strokeRect(at.x - 0.12, at.y - 0.12, 0.24, 0.24);
      }
    } else if (iface === "localize" && d.Hypotheses && d.Hypotheses.hypoths.length) {
      const best = d.Hypotheses.hypoths.reduce((a, b) => (b.alpha > a.alpha ? b : a));
      const m = pose2(best.mean);
      ctx.strokeStyle = "#6a3d9a";
      ctx.lineWidth = 2 * px;
      ctx.beginPath();
      ctx.arc(m.x, m.y, 0.35, 0, 2 * Math.PI);
      ctx.moveTo(m.x, m.y);
      ctx.lineTo(m.x + 0.5 * Math.cos(m.a), m.y + 0.5 * Math.sin(m.a));
      ctx.stroke();
    } else if (iface === "planner" && d.State && d.State.valid && !d.State.done) {
      const s = d.State;
      ctx.strokeStyle = colour;
      ctx.lineWidth = 2 * px;
      ctx.setLineDash([6 * px, 4 * px]);
      ctx.beginPath();
      ctx.moveTo(s.pos.px, s.pos.py);
      ctx.lineTo(s.waypoint.px, s.waypoint.py);
      ctx.lineTo(s.goal.px, s.goal.py);
      ctx.stroke();
      ctx.setLineDash([]);
      cross(s.goal.px, s.goal.py, 0.25, colour);
    }
  }
  for (const { index, d } of bases(robot)) {
    const p = pose2(d.State.pos);
    const size = d.geom && d.geom.size ? d.geom.size : { sl: 0.5, sw: 0.4 };
    const off = mount(d.geom);
    ctx.save();
    ctx.translate(p.x, p.y);
    ctx.rotate(p.a);
    ctx.translate(off.x, off.y);
    ctx.fillStyle = colour;
    ctx.fillRect(-size.sl / 2, -size.sw / 2, size.sl, size.sw);
    ctx.strokeStyle = "#fff";
    ctx.lineWidth = 2 * px;
    ctx.beginPath();
    ctx.moveTo(0, 0);
    ctx.lineTo(size.sl / 2, 0);
    ctx.stroke();
    if (selected && selected.robot === robotName(robot) && selected.index === index) {
      ctx.strokeStyle = "#b86e00";
      ctx.lineWidth = 3 * px;
      ctx.strokeRect(-size.sl / 2 - 0.08, -size.sw / 2 - 0.08, size.sl + 0.16, size.sw + 0.16);
    }
    ctx.restore();
  }
  ctx.globalAlpha = 1;
}

function robotName(robot) {
  for (const [name, r] of robots) if (r === robot) return name;
  return null;
}

function rays(sensor, bearings, maxRange, colour) {
  ctx.fillStyle = colour.replace("hsl", "hsla").replace(")", ",0.08)");
  ctx.beginPath();
  ctx.moveTo(sensor.x, sensor.y);
  const hits = [];
  for (const [bearing, r] of bearings) {
    const range = r === null || !(r > 0) ? maxRange : Math.min(r, maxRange);
    const a = sensor.a + bearing;
    const x = sensor.x + range * Math.cos(a), y = sensor.y + range * Math.sin(a);
    ctx.lineTo(x, y);
    if (r !== null && r > 0 && r < maxRange) hits.push([x, y]);
  }
  ctx.closePath();
  ctx.fill();
  ctx.fillStyle = colour;
  const dot = 3 / view.zoom;
  for (const [x, y] of hits) ctx.fillRect(x - dot / 2, y - dot / 2, dot, dot);
}

function beam(at, range, colour) {
  if (range === null || !(range > 0)) return;
  ctx.strokeStyle = colour.replace("hsl", "hsla").replace(")", ",0.45)");
  ctx.lineWidth = 1.5 / view.zoom;
  ctx.beginPath();
  ctx.moveTo(at.x, at.y);
  ctx.lineTo(at.x + range * Math.cos(at.a), at.y + range * Math.sin(at.a));
  ctx.stroke();
}

function cross(x, y, r, colour) {
  ctx.strokeStyle = colour;
  ctx.beginPath();
  ctx.moveTo(x - r, y - r); ctx.lineTo(x + r, y + r);
  ctx.moveTo(x - r, y + r); ctx.lineTo(x + r, y - r);
  ctx.stroke();
}

// Drives the relay's web page in Debian's Chromium, headless, through Playwright, and prints
// what it saw as one line of JSON for the Rust test that started the robots to check.
//
//   node page.mjs draw    URL OUT.png                 robots' poses on the page and the colour under each,
//                                                     the names written, the world's walls and their colour
//
// VIEWPORT=WIDTHxHEIGHT sets the window (1200x750 by default; 390x844 is a phone).
//   node page.mjs follow  URL ROBOT SECONDS           the page's pose of ROBOT, sampled
//   node page.mjs command URL ROBOT X Y KEYS          click ROBOT, click (X, Y) unless X is -; with KEYS 1 hold ← 1 s
//   node page.mjs link    URL ROBOT SECONDS           ROBOT's link states as the page showed them
//   node page.mjs find    URL TEXT                    the summary and rows listed, before and after typing TEXT in Find
//   node page.mjs watch   URL SECONDS                 once every robot has a pose prints WATCHING, then after
//                                                     SECONDS the listed rows' position2d Hz (min, median), their
//                                                     devices shown and not, and the robots with a scan drawn
import { chromium } from "playwright-core";

const CHROMIUM = process.env.CHROMIUM || "/usr/bin/chromium";
const [scenario, url, ...args] = process.argv.slice(2);

const browser = await chromium.launch({
  executablePath: CHROMIUM,
  args: ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
    "--disable-component-update", "--no-first-run", "--disable-quic", "--disable-sync"],
});
const errors = [];
try {
  const size = (process.env.VIEWPORT || "1200x750").split("x").map(Number);
  const page = await browser.newPage({ viewport: { width: size[0], height: size[1] } });
  page.on("pageerror", (e) => errors.push(e.message));
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  await page.goto(url);
  const result = await ({ draw, follow, command, link, find, watch })[scenario](page, ...args);
  console.log(JSON.stringify({ ...result, errors }));
} finally {
  await browser.close();
}

// Until every robot the page knows has a pose (and a map, where one is served), at most 15 s.
async function settle(page) {
  await page.waitForFunction(() => {
    const w = window.playerWeb;
    if (!w || w.robots.size === 0) return false;
    for (const [name] of w.robots) if (!w.screenOf(name, 0)) return false;
    return true;
  }, null, { timeout: 15000 });
  await page.waitForTimeout(1500); // map tiles inflate asynchronously; rows come once a second
}

async function watch(page, seconds) {
  await page.waitForFunction(() => {
    const w = window.playerWeb;
    if (!w || w.robots.size === 0 || !document.querySelector("#rows tbody tr")) return false;
    for (const [name] of w.robots) if (!w.screenOf(name, 0)) return false;
    return true;
  }, null, { timeout: 60000, polling: 500 });
  console.log("WATCHING");
  await page.waitForTimeout(Number(seconds) * 1000);
  // The rows as the page lists them (its first 60), read from what it shows.
  return await page.evaluate(() => {
    const w = window.playerWeb;
    const hz = [];
    let shown = 0, unshown = 0;
    for (const span of document.querySelectorAll("#rows tbody tr span.device")) {
      const text = span.textContent;
      const rate = /^position2d:\d+ ([0-9.]+) Hz/.exec(text);
      if (rate) hz.push(Number(rate[1]));
      if (text.includes("not shown")) unshown += 1;
      else shown += 1;
    }
    hz.sort((a, b) => a - b);
    let scans = 0;
    for (const robot of w.robots.values()) {
      const laser = robot.devices.get("laser:0");
      if (laser && laser.Scan) scans += 1;
    }
    return {
      robots: w.robots.size,
      listed: document.querySelectorAll("#rows tbody tr").length,
      poseHz: { min: hz[0] ?? 0, median: hz[Math.floor(hz.length / 2)] ?? 0 },
      shown,
      unshown,
      scans,
    };
  });
}

async function draw(page, out) {
  await settle(page);
  await page.screenshot({ path: out });
  const robots = await page.evaluate(() => {
    const w = window.playerWeb;
    const canvas = document.getElementById("view");
    const ctx = canvas.getContext("2d");
    const box = canvas.getBoundingClientRect();
    const ratio = window.devicePixelRatio || 1;
    const seen = {};
    for (const [name, robot] of w.robots) {
      const d = robot.devices.get("position2d:0");
      const [sx, sy] = w.screenOf(name, 0);
      // The body's colour around its centre (the heading line is drawn white through it).
      const pixels = [];
      for (const dx of [-4, 0, 4]) {
        for (const dy of [-4, 0, 4]) {
          const x = Math.round(sx * ratio) + dx, y = Math.round(sy * ratio) + dy;
          pixels.push([...ctx.getImageData(x, y, 1, 1).data].slice(0, 3));
        }
      }
      seen[name] = { pose: [d.State.pos.px, d.State.pos.py, d.State.pos.pa], css: [sx + box.left, sy + box.top], pixels, maps: robot.maps.size };
    }
    return seen;
  });
  const layout = await page.evaluate(() => {
    const r = (id) => { const b = document.querySelector(id).getBoundingClientRect(); return [b.left, b.top, b.width, b.height]; };
    return { view: r("#view"), rows: r("#rows"), rowCount: document.querySelectorAll("#rows tbody tr").length };
  });
  // The walls the page was sent, and the colour drawn at the middle of the largest ones.
  const walls = await page.evaluate(() => {
    const w = window.playerWeb;
    if (!w.walls) return null;
    const ctx = document.getElementById("view").getContext("2d");
    const ratio = window.devicePixelRatio || 1;
    const area = (r) => (r[2] - r[0]) * (r[3] - r[1]);
    const largest = [...w.walls.rects].sort((a, b) => area(b) - area(a)).slice(0, 8);
    const pixels = largest.map((r) => {
      const [sx, sy] = w.worldToCss((r[0] + r[2]) / 2, (r[1] + r[3]) / 2);
      return [...ctx.getImageData(Math.round(sx * ratio), Math.round(sy * ratio), 1, 1).data].slice(0, 3);
    });
    return { rects: w.walls.rects.length, polygons: w.walls.polygons.length, pixels };
  });
  const labels = await page.evaluate(() => window.playerWeb.labels.map((l) => l.name));
  return { robots, layout, walls, labels };
}

async function follow(page, robot, seconds) {
  await settle(page);
  const samples = [];
  const end = Date.now() + Number(seconds) * 1000;
  while (Date.now() < end) {
    samples.push(await page.evaluate((name) => {
      const d = window.playerWeb.robots.get(name).devices.get("position2d:0");
      return [d.State.pos.px, d.State.pos.py];
    }, robot));
    await page.waitForTimeout(200);
  }
  return { samples };
}

async function command(page, robot, x, y, keys) {
  await settle(page);
  const at = async (fn, ...a) => {
    const [sx, sy] = await page.evaluate(fn, a);
    const box = await page.locator("#view").boundingBox();
    return [sx + box.x, sy + box.y];
  };
  const [rx, ry] = await at(([name]) => window.playerWeb.screenOf(name, 0), robot);
  await page.mouse.click(rx, ry);
  const selected = await page.evaluate(() => window.playerWeb.selected);
  if (x !== "-") {
    const [gx, gy] = await at(([gx, gy]) => window.playerWeb.worldToCss(gx, gy), Number(x), Number(y));
    await page.mouse.click(gx, gy);
  }
  if (keys === "1") {
    await page.keyboard.down("ArrowLeft");
    await page.waitForTimeout(1000);
    await page.keyboard.up("ArrowLeft");
  }
  await page.waitForTimeout(300);
  return {
    selected,
    controller: await page.evaluate(() => window.playerWeb.controller),
    role: await page.textContent("#role"),
    refused: await page.textContent("#refused"),
  };
}

async function link(page, robot, seconds) {
  await settle(page);
  const states = [];
  const end = Date.now() + Number(seconds) * 1000;
  while (Date.now() < end) {
    const now = await page.evaluate((name) => {
      const r = window.playerWeb.robots.get(name);
      const row = document.querySelector(`#rows tr[data-robot="${name}"] td:nth-child(2)`);
      return { state: r.link.state, posed: !!r.devices.get("position2d:0"), row: row ? row.textContent : null };
    }, robot);
    const last = states[states.length - 1];
    if (!last || last.state !== now.state || last.posed !== now.posed) states.push(now);
    if (states.some((s) => s.state === "reconnecting") && now.state === "connected" && now.posed) break;
    await page.waitForTimeout(100);
  }
  return { states };
}

async function find(page, text) {
  await settle(page);
  const listed = () => page.evaluate(() => ({
    summary: document.getElementById("summary").textContent,
    rows: [...document.querySelectorAll("#rows tbody tr")].map((tr) => tr.dataset.robot),
  }));
  const before = await listed();
  await page.fill("#find", text);
  await page.waitForTimeout(200);
  const after = await listed();
  return { before, after };
}

// The robots' rows under the view: one for each robot the relay lists (its link and its
// devices' rates), the selected one first, narrowed by the Find field. Loaded before app.js,
// whose selection (selected, select) these use when called.
"use strict";

// ---- rows -----------------------------------------------------------------------------

// At most this many rows are listed: with a thousand robots, the selected one, those the
// Find field matches and a summary of the rest are what a person can use.
const MAX_ROWS = 60;
let lastRows = [];
document.getElementById("find").addEventListener("input", () => showRows(lastRows));

function showRows(rows) {
  lastRows = rows;
  const words = document.getElementById("find").value.toLowerCase().split(/\s+/).filter(Boolean);
  const said = (row) => [row.robot, row.link.state, ...row.devices.map((d) => d.device)].join(" ").toLowerCase();
  const matching = rows.filter((row) => words.every((w) => said(row).includes(w)));
  const first = (row) => (selected && selected.robot === row.robot ? 0 : 1);
  matching.sort((a, b) => first(a) - first(b)); // stable: the relay's order otherwise
  const states = new Map();
  for (const row of rows) states.set(row.link.state, (states.get(row.link.state) || 0) + 1);
  const parts = [...states].map(([state, n]) => `${n} ${state}`);
  let summary = `${rows.length} robot${rows.length === 1 ? "" : "s"}` + (parts.length ? `: ${parts.join(", ")}` : "");
  if (words.length) summary += ` · ${matching.length} found`;
  if (matching.length > MAX_ROWS) summary += ` · the first ${MAX_ROWS} listed, Find narrows`;
  document.getElementById("summary").textContent = summary;
  const body = document.querySelector("#rows tbody");
  body.replaceChildren();
  rows = matching.slice(0, MAX_ROWS);
  for (const row of rows) {
    const tr = document.createElement("tr");
    tr.dataset.robot = row.robot;
    if (selected && selected.robot === row.robot) tr.className = "selected";
    const link = row.link.state + (row.link.why ? `: ${row.link.why}` : "");
    // Text from the wire goes in as text, never as markup.
    const cell = (text, className) => {
      const td = document.createElement("td");
      td.textContent = text;
      if (className) td.className = className;
      return td;
    };
    const devices = document.createElement("td");
    for (const d of row.devices.sort((a, b) => a.device.localeCompare(b.device))) {
      const age = d.age === null ? "no data" : `${d.age.toFixed(1)} s`;
      const hz = d.hz >= 10 ? d.hz.toFixed(0) : d.hz.toFixed(1);
      const span = document.createElement("span");
      span.className = "device" + (!d.shown ? " unshown" : d.age === null || d.age > 2 ? " stale" : "");
      // A device no page shows is not subscribed: it has no rate to give.
      span.textContent = d.shown ? `${d.device} ${hz} Hz · ${age}` : `${d.device} · not shown`;
      devices.append(span);
    }
    tr.append(cell(row.robot), cell(link, `link-${row.link.state}`), devices);
    tr.addEventListener("click", () => select(row.robot, 0));
    body.append(tr);
  }
}

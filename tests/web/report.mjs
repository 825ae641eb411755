// Opens player-grade's report.html in Debian's Chromium, headless, through Playwright, and
// prints what a teacher would see as one line of JSON for the Rust test to check: the rows
// (student, score), whether every path picture loaded, the page's errors; and a screenshot.
//
//   node report.mjs FILE.html OUT.png
import { chromium } from "playwright-core";
import { pathToFileURL } from "node:url";

const CHROMIUM = process.env.CHROMIUM || "/usr/bin/chromium";
const [file, out] = process.argv.slice(2);

const browser = await chromium.launch({
  executablePath: CHROMIUM,
  args: ["--headless", "--no-sandbox", "--disable-gpu", "--disable-background-networking",
    "--disable-component-update", "--no-first-run"],
});
const errors = [];
try {
  const page = await browser.newPage({ viewport: { width: 1300, height: 900 } });
  page.on("pageerror", (e) => errors.push(e.message));
  page.on("console", (m) => { if (m.type() === "error") errors.push(m.text()); });
  page.on("requestfailed", (r) => errors.push(`${r.url()}: ${r.failure()?.errorText}`));
  await page.goto(pathToFileURL(file).href, { waitUntil: "load" });
  await page.screenshot({ path: out, fullPage: true });
  const seen = await page.evaluate(() => ({
    title: document.querySelector("h1")?.textContent,
    rows: [...document.querySelectorAll("tbody tr")].map((row) => ({
      name: row.querySelector(".name")?.textContent,
      score: row.querySelector(".score")?.textContent,
      passed: row.querySelectorAll("td.pass").length,
      failed: row.querySelectorAll("td.fail").length,
      picture: (() => {
        const img = row.querySelector("img");
        return img ? { loaded: img.complete && img.naturalWidth > 0, width: img.naturalWidth } : null;
      })(),
    })),
  }));
  console.log(JSON.stringify({ ...seen, errors }));
} finally {
  await browser.close();
}

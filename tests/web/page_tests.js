// Tests of the browser page (build/web/chainbreak.html) in Debian's Chromium, driven by
// playwright-core (no browser download: executablePath /usr/bin/chromium). The page is opened
// from file://, as a student opens it. ctest runs one group per test (tests/CMakeLists.txt):
//   node page_tests.js GROUP
// Environment: CHAINBREAK_PAGE (the page), CHAINBREAK_EXE (the CLI it is compared with),
// CHAINBREAK_SCENES (the shipped scenes), CHAINBREAK_FUZZ_SECONDS (fuzz, default 30).
"use strict";
const assert = require("node:assert/strict");
const { execFileSync } = require("node:child_process");
const fs = require("node:fs");
const os = require("node:os");
const path = require("node:path");

let chromium, axeSource;
try {
  ({ chromium } = require("playwright-core"));
  axeSource = fs.readFileSync(require.resolve("axe-core/axe.min.js"), "utf8");
} catch (e) {
  console.error("tests/web needs its npm packages: npm ci --prefix tests/web (" + e.message + ")");
  process.exit(1);
}

const PAGE = process.env.CHAINBREAK_PAGE;
const EXE = process.env.CHAINBREAK_EXE;
const SCENES = process.env.CHAINBREAK_SCENES;
for (const [name, value] of [["CHAINBREAK_PAGE", PAGE], ["CHAINBREAK_EXE", EXE], ["CHAINBREAK_SCENES", SCENES]])
  if (!value) throw new Error(name + " is not set (ctest sets it)");
const PAGE_URL = "file://" + path.resolve(PAGE);

async function launch() {
  return chromium.launch({
    executablePath: "/usr/bin/chromium",
    args: ["--enable-unsafe-swiftshader", "--use-angle=swiftshader", "--no-sandbox"],
  });
}

// A page at `query`, ready, with every console error and uncaught exception collected.
async function open(browser, query = "", options = {}) {
  const context = await browser.newContext({ acceptDownloads: true, ...options });
  const page = await context.newPage();
  const problems = [];
  page.on("console", (m) => { if (m.type() === "error") problems.push("console: " + m.text()); });
  page.on("pageerror", (e) => problems.push("exception: " + e.message));
  await page.goto(PAGE_URL + query);
  await page.evaluate(() => window.chainbreak.ready);
  return { page, problems, context };
}

// Every shipped scene, as "name" (the page's ?scene= key) and its file.
function shippedScenes() {
  const out = [];
  const walk = (dir) => {
    for (const name of fs.readdirSync(dir).sort()) {
      const p = path.join(dir, name);
      if (fs.statSync(p).isDirectory()) walk(p);
      else if (name.endsWith(".toml")) out.push({ name: name.slice(0, -5), file: p });
    }
  };
  walk(SCENES);
  return out;
}

// The scene's drive type as the scene reader sees it: the CLI's own answer is in the page too,
// but the test asks neither; it reads the one line the schema requires.
function driveType(file) {
  const m = fs.readFileSync(file, "utf8").match(/^\s*type\s*=\s*"(\w+)"/m);
  return m ? m[1] : "ramp";
}

function cliBreaks(file) {
  const out = execFileSync(EXE, ["run", file], { encoding: "utf8", stdio: ["ignore", "pipe", "pipe"] });
  const summary = JSON.parse(out.slice(out.indexOf("{")));
  return summary;
}

const groups = {};

// The page's breaks equal `chainbreak run`'s bit for bit (ramp, step, impulses, table), within
// 1e-12 for a sine (libm's sin may differ in the last bit between glibc and Emscripten's musl);
// an expression drive is refused with the page's message (no muParser in WebAssembly).
groups.breaks = async (browser) => {
  let compared = 0;
  for (const { name, file } of shippedScenes()) {
    const type = driveType(file);
    const { page, problems, context } = await open(browser, "?scene=" + encodeURIComponent(name));
    if (type === "expr") {
      const error = await page.textContent("#scene-error");
      assert.match(error, /expression drives need the command-line program/, name);
      await context.close();
      continue;
    }
    const cli = cliBreaks(file);
    const state = await page.evaluate(() => window.chainbreak.runTo(1e300));
    assert.equal(await page.textContent("#scene-error"), "", name + ": the page refused the scene");
    assert.equal(state.breaks.length, cli.breaks.length,
                 name + ": " + JSON.stringify(state.breaks) + " vs " + JSON.stringify(cli.breaks));
    for (let i = 0; i < cli.breaks.length; ++i) {
      const p = state.breaks[i], c = cli.breaks[i];
      assert.equal(p.spring, c.spring, name + " break " + i);
      if (type === "sine" || type === "expr")
        assert.ok(Math.abs(p.tau - c.tau) <= 1e-12 * Math.max(1, Math.abs(c.tau)),
                  name + " break " + i + ": " + p.tau + " vs " + c.tau);
      else
        assert.ok(Object.is(p.tau, c.tau), name + " break " + i + ": tau " + p.tau + " (page) vs " +
                  c.tau + " (chainbreak run): not the same double");
    }
    assert.deepEqual(problems, [], name);
    console.log(`  ${name} (${type}): ${cli.breaks.length} breaks equal, first ` +
                (cli.breaks.length ? `spring ${cli.breaks[0].spring} at tau ${cli.breaks[0].tau}` : "none"));
    compared += type === "sine" ? 0 : 1;
    await context.close();
  }
  assert.ok(compared >= 10, "too few scenes compared bit for bit: " + compared);
};

module.exports = { groups, open, launch, shippedScenes, PAGE_URL, EXE, SCENES, axeSource };

if (require.main === module) {
  const name = process.argv[2];
  const group = groups[name] || (require("./page_ui_tests.js").groups || {})[name];
  if (!group) {
    console.error("usage: node page_tests.js GROUP; groups: " + Object.keys(groups).join(", "));
    process.exit(2);
  }
  (async () => {
    const browser = await launch();
    const start = Date.now();
    try {
      await group(browser);
      console.log(`web ${name}: passed in ${((Date.now() - start) / 1000).toFixed(1)} s`);
    } catch (e) {
      console.error(`web ${name}: FAILED: ${e.stack || e}`);
      process.exitCode = 1;
    } finally {
      await browser.close();
    }
  })();
}

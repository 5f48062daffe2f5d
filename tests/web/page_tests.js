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

// The drive's kind as the scene file names it ([drive] type; a ramp when absent), to pick the
// comparison: bit for bit, or within 1e-12 for a sine.
function driveType(file) {
  const m = fs.readFileSync(file, "utf8").match(/^\s*type\s*=\s*"(\w+)"/m);
  return m ? m[1] : "ramp";
}

// `chainbreak run FILE --set k=v ...`: its JSON summary.
function cliRun(file, sets = []) {
  const args = ["run", file];
  for (const [k, v] of sets) args.push("--set", k + "=" + v);
  return JSON.parse(execFileSync(EXE, args, { encoding: "utf8", stdio: ["ignore", "pipe", "pipe"] }));
}

const groups = {};

// Expressions the breaks group runs on the shipped expression scene (chain.threshold = 0.5),
// beside the scene's own: each breaks the chain.
const kExpressions = [
  "0.02*t", "t/50", "2*t/3/60", "t^2/2000", "t<10 ? 0.1*t : 1", "0.5*(1+tanh((t-30)/5))",
  "min(0.02*t, 1) + 0.1*sin(2*pi*t/40)", "sqrt(t)/5", "abs(sin(t/8))^3 + 0.3",
  "(t>5 && t<25) ? 0.8 : 0", "max(0, 1 - abs(t-20)/10)", "log(1+t)/4", "-exp(-0.04*(t-20)^2)",
  "sum(0.01*t, cos(t/7)/10, _e/20) + atan2(t, 50)/4",
];

// The page's breaks equal `chainbreak run`'s bit for bit (ramp, step, impulses, table), within
// 1e-12 in tau for a sine and an expression drive (libm's sin, exp, ... may differ in the last
// bit between glibc and Emscripten's musl; the page's expression evaluator is the project's
// own, src/web/shim/expression.cpp, the CLI's is muParser), the spring exactly. Every scene
// runs as shipped and with chain.threshold = 0.5 (through the link's keys and --set), so the
// unbreakable ones (step, impulses, table, sine) break too.
groups.breaks = async (browser) => {
  let compared = 0;
  const broken = {};
  const largest = {};  // the largest |tau_page - tau_cli| of a break, by drive kind
  const close = (type) => type === "sine" || type === "expr";
  for (const { name, file } of shippedScenes()) {
    const type = driveType(file);
    for (const sets of [[], [["chain.threshold", "0.5"]]]) {
      const query = "?scene=" + encodeURIComponent(name) +
                    sets.map(([k, v]) => "&" + k + "=" + encodeURIComponent(v)).join("");
      const { page, problems, context } = await open(browser, query);
      const cli = cliRun(file, sets);
      const state = await page.evaluate(() => window.chainbreak.runTo(Infinity));
      assert.equal(await page.textContent("#scene-error"), "", query + ": the page refused the scene");
      assert.equal(state.tau, cli.tau_end, query + ": the page stopped elsewhere");
      assert.equal(state.breaks.length, cli.breaks.length,
                   query + ": " + JSON.stringify(state.breaks) + " vs " + JSON.stringify(cli.breaks));
      for (let i = 0; i < cli.breaks.length; ++i) {
        const p = state.breaks[i], c = cli.breaks[i];
        assert.equal(p.spring, c.spring, query + " break " + i);
        if (close(type)) {
          const d = Math.abs(p.tau - c.tau);
          largest[type] = Math.max(largest[type] || 0, d);
          assert.ok(d <= 1e-12 * Math.max(1, Math.abs(c.tau)),
                    query + " break " + i + ": " + p.tau + " vs " + c.tau);
        }
        else
          assert.ok(Object.is(p.tau, c.tau), query + " break " + i + ": tau " + p.tau +
                    " (page) vs " + c.tau + " (chainbreak run): not the same double");
      }
      // The whole run, not only its breaks: the energy books equal the CLI's to the bit.
      for (const key of ["kinetic", "potential", "work", "dissipated", "break_loss"]) {
        const p = state.energy[key], c = cli.energy[key];
        if (close(type))
          assert.ok(Math.abs(p - c) <= 1e-12 * Math.max(1, Math.abs(c)), query + " " + key);
        else
          assert.ok(Object.is(p, c) || (p === 0 && c === 0), query + " energy." + key + ": " + p + " vs " + c);
      }
      assert.deepEqual(problems, [], query);
      console.log(`  ${query} (${type}): ${cli.breaks.length} breaks equal` +
                  (cli.breaks.length ? `, first spring ${cli.breaks[0].spring} at tau ${cli.breaks[0].tau}` : ""));
      if (!close(type)) compared += cli.breaks.length;
      broken[type] = (broken[type] || 0) + cli.breaks.length;
      await context.close();
    }
  }
  // Expression drives beyond the shipped one, typed into the page's expression field (so the
  // field's wiring is tested too) and given to the CLI as --set drive.expr: functions, the
  // ternary, logic, powers (muParser rewrites t^2, c*t+d; the page's evaluator mirrors that).
  for (const { name, file } of shippedScenes().filter((s) => driveType(s.file) === "expr")) {
    const { page, problems, context } = await open(browser, "?scene=" + encodeURIComponent(name) +
                                                            "&chain.threshold=0.5");
    for (const expr of kExpressions) {
      await page.fill("#k-drive-expr", expr);
      await page.dispatchEvent("#k-drive-expr", "change");
      assert.equal(await page.textContent("#k-drive-expr-error"), "", expr + ": refused");
      const state = await page.evaluate(() => window.chainbreak.runTo(Infinity));
      const cli = cliRun(file, [["chain.threshold", "0.5"], ["drive.expr", expr]]);
      assert.equal(state.tau, cli.tau_end, expr + ": the page stopped elsewhere");
      assert.equal(state.breaks.length, cli.breaks.length, expr + ": " +
                   JSON.stringify(state.breaks) + " vs " + JSON.stringify(cli.breaks));
      for (let i = 0; i < cli.breaks.length; ++i) {
        const p = state.breaks[i], c = cli.breaks[i];
        assert.equal(p.spring, c.spring, expr + " break " + i);
        const d = Math.abs(p.tau - c.tau);
        largest.expr = Math.max(largest.expr || 0, d);
        assert.ok(d <= 1e-12 * Math.max(1, Math.abs(c.tau)), expr + " break " + i + ": " + p.tau +
                  " vs " + c.tau);
      }
      for (const key of ["kinetic", "potential", "work", "dissipated", "break_loss"])
        assert.ok(Math.abs(state.energy[key] - cli.energy[key]) <=
                  1e-12 * Math.max(1, Math.abs(cli.energy[key])), expr + " " + key);
      console.log(`  ${name} drive.expr = "${expr}": ${cli.breaks.length} breaks equal`);
      broken.expr = (broken.expr || 0) + cli.breaks.length;
    }
    assert.deepEqual(problems, [], name);
    await context.close();
  }
  for (const type of ["ramp", "step", "impulses", "table", "sine", "expr"])
    assert.ok(broken[type] > 0, "no shipped scene with a " + type + " drive broke: nothing compared");
  console.log(`  ${compared} breaks compared bit for bit; within 1e-12: ` +
              ["sine", "expr"].map((t) => `${broken[t]} ${t} breaks, largest |dtau| ${largest[t] || 0}`)
                .join(", "));
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

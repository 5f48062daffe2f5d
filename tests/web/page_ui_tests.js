// The page's controls, link, files, accessibility, a random-input fuzz and a pixel check
// (run through page_tests.js: node page_tests.js GROUP).
"use strict";
const assert = require("node:assert/strict");
const { execFileSync } = require("node:child_process");
const fs = require("node:fs");
const os = require("node:os");
const path = require("node:path");
const { open, EXE, SCENES, axeSource } = require("./page_tests.js");

const groups = {};

// ?scene=NAME picks a shipped scene; every other key is a scene key, as --set.
groups.url = async (browser) => {
  const { page, problems } = await open(browser, "?scene=fast_pull&drive.beta=0.05&chain.gamma=0.01");
  assert.equal(await page.inputValue("#k-drive-beta"), "0.05");
  assert.equal(await page.inputValue("#k-chain-gamma"), "0.01");
  assert.equal(await page.inputValue("#preset"), "fast_pull");
  // The copy-link field carries the same setting back.
  const link = new URL(await page.inputValue("#link"));
  assert.equal(link.searchParams.get("scene"), "fast_pull");
  assert.equal(link.searchParams.get("drive.beta"), "0.05");
  assert.equal(link.searchParams.get("chain.gamma"), "0.01");
  // ... and the run is the CLI's with the same --set.
  const cli = JSON.parse(execFileSync(EXE, ["run", path.join(SCENES, "regimes/fast_pull.toml"),
    "--set", "drive.beta=0.05", "--set", "chain.gamma=0.01"], { encoding: "utf8" }));
  const state = await page.evaluate(() => window.chainbreak.runTo(1e300));
  assert.deepEqual(state.breaks.map((b) => [b.spring, b.tau]), cli.breaks.map((b) => [b.spring, b.tau]));
  // A control changes the link.
  await page.fill("#k-chain-beads", "40");
  await page.press("#k-chain-beads", "Enter");
  await page.dispatchEvent("#k-chain-beads", "change");
  assert.equal(new URL(await page.inputValue("#link")).searchParams.get("chain.beads"), "40");
  assert.equal((await page.evaluate(() => window.chainbreak.state())).beads, 40);
  assert.deepEqual(problems, []);
  // An extreme but valid threshold (found by the fuzz, seed 1): the breaking map beside the
  // run once searched exact first breaks up to tau = 4e11 and held the page for hours.
  const started = Date.now();
  const far = await open(browser, "?scene=anomalous_breaking&chain.threshold=1e9");
  const farState = await far.page.evaluate(() => window.chainbreak.runTo(5));
  assert.ok(farState.tau >= 5 && farState.breaks.length === 0, JSON.stringify(farState));
  assert.ok(Date.now() - started < 20000, `the page took ${Date.now() - started} ms`);
  assert.deepEqual(far.problems, []);
};

// A bad scene anywhere gets the reader's message next to it, never a blank page.
groups.errors = async (browser) => {
  // In the URL: the CLI's message for the same --set, and the default scene shown instead.
  const { page, problems } = await open(browser, "?scene=anomalous_breaking&chain.gamma=-1");
  const urlError = await page.textContent("#scene-error");
  let cliError = "";
  try {
    execFileSync(EXE, ["run", path.join(SCENES, "anomalous_breaking.toml"), "--set", "chain.gamma=-1"],
                 { encoding: "utf8", stdio: ["ignore", "pipe", "pipe"] });
  } catch (e) {
    cliError = e.stderr.trim();
  }
  assert.ok(cliError.length > 0, "the CLI accepted chain.gamma=-1");
  assert.ok(urlError.startsWith("In the link: "), urlError);
  // The CLI prefixes "chainbreak: " or the like; the reader's own sentence must be the same.
  const reader = urlError.slice("In the link: ".length);
  assert.ok(cliError.includes(reader), `page: ${reader}\nCLI: ${cliError}`);
  assert.equal((await page.evaluate(() => window.chainbreak.state())).beads, 30);
  assert.ok((await page.textContent("#scene-title")).length > 0);
  // load() throws an Error carrying the reader's message, with a line and column.
  const thrown = await page.evaluate(() => {
    try {
      window.chainbreak.load("[chain]\nbeads = 30\ngamma = \"x\"\n");
      return "";
    } catch (e) {
      return e instanceof Error ? e.message : "not an Error: " + e;
    }
  });
  assert.match(thrown, /scene\.toml:3:\d+: /, thrown);
  // A field: the message beside it, the field marked invalid, the run unchanged.
  await page.fill("#k-chain-threshold", "-2");
  await page.dispatchEvent("#k-chain-threshold", "change");
  assert.match(await page.textContent("#k-chain-threshold-error"), /threshold/);
  assert.equal(await page.getAttribute("#k-chain-threshold", "aria-invalid"), "true");
  // An opened file that is not a scene.
  const bad = path.join(os.tmpdir(), "chainbreak_web_bad.toml");
  fs.writeFileSync(bad, "[chain\nbeads = 30\n");
  await page.setInputFiles("#open", bad);
  await page.waitForFunction(() => document.getElementById("scene-error").textContent.includes("chainbreak_web_bad.toml:"));
  fs.unlinkSync(bad);
  assert.deepEqual(problems, []);
};

// Snapshot as PNG; save the scene as .toml and read it back with the CLI.
groups.files = async (browser) => {
  const { page, problems } = await open(browser, "?scene=step_pulse");
  await page.evaluate(() => window.chainbreak.runTo(20));
  const [png] = await Promise.all([page.waitForEvent("download"), page.click("#save-png")]);
  assert.match(png.suggestedFilename(), /^step_pulse_tau_20\.000\.png$/);
  const pngPath = path.join(os.tmpdir(), "chainbreak_web_snapshot.png");
  await png.saveAs(pngPath);
  const bytes = fs.readFileSync(pngPath);
  assert.deepEqual([...bytes.subarray(0, 8)], [137, 80, 78, 71, 13, 10, 26, 10], "not a PNG");
  assert.equal(bytes.readUInt32BE(16), 1280);
  assert.equal(bytes.readUInt32BE(20), 720);
  fs.unlinkSync(pngPath);
  const [toml] = await Promise.all([page.waitForEvent("download"), page.click("#save-toml")]);
  const tomlPath = path.join(os.tmpdir(), "chainbreak_web_saved.toml");
  await toml.saveAs(tomlPath);
  const cliSaved = JSON.parse(execFileSync(EXE, ["run", tomlPath], { encoding: "utf8" }));
  const cliShipped = JSON.parse(execFileSync(EXE, ["run", path.join(SCENES, "step_pulse.toml")], { encoding: "utf8" }));
  assert.deepEqual(cliSaved.breaks, cliShipped.breaks);
  fs.unlinkSync(tomlPath);
  assert.deepEqual(problems, []);
};

// The theme follows prefers-color-scheme, and the control overrides it (page and canvas).
groups.theme = async (browser) => {
  const background = async (page) => page.evaluate(() => {
    const { rgba } = window.chainbreak.pixels();
    return [rgba[0], rgba[1], rgba[2]];
  });
  const dark = await open(browser, "", { colorScheme: "dark" });
  assert.equal(await dark.page.getAttribute("html", "data-theme"), "dark");
  const darkBg = await background(dark.page);
  assert.ok(darkBg.every((c) => c < 60), "dark canvas background " + darkBg);
  const light = await open(browser, "", { colorScheme: "light" });
  assert.equal(await light.page.getAttribute("html", "data-theme"), "light");
  const lightBg = await background(light.page);
  assert.ok(lightBg.every((c) => c > 200), "light canvas background " + lightBg);
  await light.page.selectOption("#theme", "dark");
  assert.equal(await light.page.getAttribute("html", "data-theme"), "dark");
  assert.deepEqual(await background(light.page), darkBg);
  assert.equal(new URL(await light.page.inputValue("#link")).searchParams.get("render.theme"), "dark");
  assert.deepEqual([...dark.problems, ...light.problems], []);
};

// Keyboard only: Tab reaches every control; Space plays; → steps; the live region speaks.
groups.keyboard = async (browser) => {
  const { page, problems } = await open(browser, "?scene=ramp_pulled_end");
  const controls = await page.evaluate(() =>
    [...document.querySelectorAll("button, select, input, canvas[tabindex]")]
      .filter((e) => !e.closest("[hidden]")).map((e) => e.id));
  const reached = new Set();
  for (let i = 0; i < controls.length * 3 && reached.size < controls.length; ++i) {
    await page.keyboard.press("Tab");
    const id = await page.evaluate(() => document.activeElement.id);
    if (controls.includes(id)) reached.add(id);
  }
  const missing = controls.filter((id) => !reached.has(id));
  assert.deepEqual(missing, [], "Tab never reached " + missing.join(", "));
  await page.focus("#chain");
  await page.keyboard.press("Space");
  assert.equal((await page.evaluate(() => window.chainbreak.state())).playing, true);
  await page.keyboard.press("Space");
  assert.equal((await page.evaluate(() => window.chainbreak.state())).playing, false);
  const before = (await page.evaluate(() => window.chainbreak.state())).tau;
  await page.keyboard.press("ArrowRight");
  assert.ok((await page.evaluate(() => window.chainbreak.state())).tau > before);
  // The Play button with Space, as a keyboard user presses it.
  await page.focus("#play");
  await page.keyboard.press("Space");
  assert.equal(await page.getAttribute("#play", "aria-pressed"), "true");
  await page.keyboard.press("Space");
  // The live region after the first break: "spring J broke at τ = T".
  const cli = JSON.parse(execFileSync(EXE, ["run", path.join(SCENES, "ramp_pulled_end.toml")], { encoding: "utf8" }));
  const first = cli.breaks[0];
  await page.evaluate((tau) => window.chainbreak.runTo(tau), first.tau + 0.05);
  const said = await page.textContent("#announce");
  assert.equal(await page.getAttribute("#announce", "aria-live"), "polite");
  assert.ok(said.startsWith(`spring ${first.spring} broke at τ = ${first.tau.toFixed(2)}`), said);
  assert.deepEqual(problems, []);
};

// axe-core on the loaded page, in both themes: no serious or critical violation.
groups.axe = async (browser) => {
  for (const colorScheme of ["light", "dark"]) {
    const { page, problems } = await open(browser, "", { colorScheme });
    await page.addScriptTag({ content: axeSource });
    const result = await page.evaluate(() => window.axe.run(document));
    const bad = result.violations.filter((v) => v.impact === "serious" || v.impact === "critical");
    assert.deepEqual(bad.map((v) => `${v.id} (${v.impact}): ${v.nodes.map((n) => n.target).join(" ")}`), [],
                     colorScheme);
    console.log(`  ${colorScheme}: ${result.passes.length} rules pass, ${result.violations.length} minor violations`);
    assert.deepEqual(problems, []);
  }
};

// PhET-style fuzzing: seeded random clicks, keys and values for CHAINBREAK_FUZZ_SECONDS (30):
// no console error, no uncaught exception, and state() still answers.
groups.fuzz = async (browser) => {
  const seconds = Number(process.env.CHAINBREAK_FUZZ_SECONDS || 30);
  let seed = Number(process.env.CHAINBREAK_FUZZ_SEED || 25);
  const random = () => {  // mulberry32: the same sequence on every machine
    seed = (seed + 0x6d2b79f5) | 0;
    let t = Math.imul(seed ^ (seed >>> 15), 1 | seed);
    t = (t + Math.imul(t ^ (t >>> 7), 61 | t)) ^ t;
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  const pick = (list) => list[Math.floor(random() * list.length)];
  const { page, problems } = await open(browser);
  const values = ["0", "1", "-1", "30", "0.02", "1e9", "", "abc", "1e-300", "2.5", "1000", "nan", "-0"];
  const keys = ["Space", "ArrowRight", "ArrowLeft", "Tab", "Enter", "Escape"];
  const end = Date.now() + seconds * 1000;
  let actions = 0;
  while (Date.now() < end) {
    const kind = random();
    const ids = await page.evaluate(() =>
      [...document.querySelectorAll("button, select, input[type=number], input[type=range], input[type=checkbox]")]
        .filter((e) => !e.closest("[hidden]") && e.id !== "save-png" && e.id !== "save-toml").map((e) => e.id));
    const id = "#" + pick(ids);
    if (process.env.CHAINBREAK_FUZZ_TRACE) console.log(`  ${actions}: ${kind.toFixed(3)} ${id}`);
    if (kind < 0.3) {
      await page.click(id).catch(() => {});
    } else if (kind < 0.55) {
      await page.keyboard.press(pick(keys));
    } else if (kind < 0.8) {
      const type = await page.getAttribute(id, "type");
      const tag = await page.evaluate((s) => document.querySelector(s).tagName, id);
      if (tag === "SELECT") {
        const options = await page.evaluate((s) => [...document.querySelector(s).options]
          .filter((o) => !o.disabled).map((o) => o.value), id);
        await page.selectOption(id, pick(options));
      } else if (type === "number") {
        // Playwright's fill refuses text a number field cannot hold ("abc", "nan"); a student
        // types it anyway, so junk goes in by the keyboard (Chromium keeps what a number field
        // accepts and marks the rest as bad input) and numbers by fill.
        const value = pick(values);
        if (process.env.CHAINBREAK_FUZZ_TRACE) console.log(`    value ${value}`);
        if (value === "" || Number.isFinite(Number(value))) {
          await page.fill(id, value);
        } else {
          await page.focus(id);
          await page.keyboard.press("Control+A");
          await page.keyboard.type(value);
        }
        await page.dispatchEvent(id, "change");
      } else if (type === "range") {
        await page.evaluate(([s, v]) => {
          const e = document.querySelector(s);
          e.value = v;
          e.dispatchEvent(new Event("input"));
        }, [id, String(-1 + random() * 4)]);
      }
    } else {
      const tau = random() * 50;
      if (process.env.CHAINBREAK_FUZZ_TRACE) console.log(`    runTo ${tau}`);
      await page.evaluate((t) => window.chainbreak.runTo(t), tau);
    }
    ++actions;
    await page.waitForTimeout(Math.floor(random() * 30));
  }
  const state = await page.evaluate(() => window.chainbreak.state());
  assert.ok(Number.isFinite(state.tau) && state.beads > 0, JSON.stringify(state));
  console.log(`  ${actions} random actions in ${seconds} s (seed ${process.env.CHAINBREAK_FUZZ_SEED || 25})`);
  assert.deepEqual(problems, []);
};

// The page's frame at tau against `chainbreak snapshot` of the same scene, size and theme.
// SwiftShader (the page) and llvmpipe (the CLI) rasterise edges differently: the tolerance is
// on the fraction of pixels off by more than 32 in a channel (under 0.1 %; measured 0.0004 %)
// and on the mean of the largest channel difference (under 0.1 of 255; measured 0.012).
groups.pixels = async (browser) => {
  const tau = 155;  // past the first break (150.86), so both layouts saw the same extremes
  for (const theme of ["dark", "light"]) {
    const dir = fs.mkdtempSync(path.join(os.tmpdir(), "chainbreak_web_px_"));
    execFileSync(EXE, ["snapshot", path.join(SCENES, "anomalous_breaking.toml"), "--at", String(tau),
                       "--size", "1280x720", "--theme", theme, "-o", dir], { stdio: "ignore" });
    const png = fs.readdirSync(dir).find((f) => f.endsWith(".png"));
    const pngBase64 = fs.readFileSync(path.join(dir, png)).toString("base64");
    fs.rmSync(dir, { recursive: true });
    const { page, problems } = await open(browser, "?scene=anomalous_breaking");
    await page.selectOption("#theme", theme);
    await page.uncheck("#plots");  // `snapshot` without --overlay: the chain alone
    await page.evaluate((t) => window.chainbreak.runTo(t), tau);
    const result = await page.evaluate(async (b64) => {
      const blob = await (await fetch("data:image/png;base64," + b64)).blob();
      const bitmap = await createImageBitmap(blob, { colorSpaceConversion: "none", premultiplyAlpha: "none" });
      const c = new OffscreenCanvas(bitmap.width, bitmap.height);
      const g = c.getContext("2d");
      g.drawImage(bitmap, 0, 0);
      const cli = g.getImageData(0, 0, bitmap.width, bitmap.height).data;
      const mine = window.chainbreak.pixels();
      let off = 0, sum = 0, max = 0;
      for (let i = 0; i < cli.length; i += 4) {
        let worst = 0;
        for (let k = 0; k < 3; ++k) worst = Math.max(worst, Math.abs(cli[i + k] - mine.rgba[i + k]));
        if (worst > 32) ++off;
        sum += worst;
        max = Math.max(max, worst);
      }
      const n = cli.length / 4;
      return { width: bitmap.width, height: bitmap.height, off: off / n, mean: sum / n, max };
    }, pngBase64);
    console.log(`  ${theme}: ${(result.off * 100).toFixed(4)} % of pixels off by > 32, mean ${result.mean.toFixed(3)}, max ${result.max}`);
    assert.equal(result.width, 1280);
    assert.equal(result.height, 720);
    assert.ok(result.off < 0.001, `${theme}: ${(result.off * 100).toFixed(3)} % of pixels differ by > 32`);
    assert.ok(result.mean < 0.1, `${theme}: mean difference ${result.mean}`);
    assert.deepEqual(problems, []);
  }
};

module.exports = { groups };

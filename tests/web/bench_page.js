// Speed of the page in headless Chromium on SwiftShader (no GPU): physics steps per second and
// frame times (snapshot + render + blit), apart, for N = 1000 and N = 1e5 (issue #25's goals:
// N = 1000 at 60 frames/s and 10 tau/s; N = 1e5 at >= 30 frames/s). Not a ctest: a measurement,
// recorded in the README ("In the browser") and tests/bench/README.md.
//
// Usage:
//   node tests/web/bench_page.js build/web/chainbreak.html
//       the physics and the playing page, as before;
//   node tests/web/bench_page.js --ceiling [--rounds 5] [--seconds 3] [--flags all|default|NAME,...]
//       [--cases a,b,...] build/web/chainbreak.html
//       the frame rate Chromium itself allows: requestAnimationFrame on an empty page, on one
//       WebGL2 canvas the size of ours cleared every frame (default and our context attributes,
//       with and without our off-screen framebuffer's blit), and our page idle and playing. Every
//       case runs once per round, in turn, so a shared machine's load falls on all of them alike;
//       the medians over rounds are printed. `--flags` adds Chromium flags that are measurement
//       controls only (a student's browser has none of them): see `controlFlags`.
"use strict";
const path = require("node:path");
const { chromium } = require("playwright-core");

const baseArgs = ["--enable-unsafe-swiftshader", "--use-angle=swiftshader"];
// Flags that change how headless Chromium paces frames; the goal's figure is the default's.
const controlFlags = {
  default: [],
  "no-vsync": ["--disable-gpu-vsync"],
  "no-limit": ["--disable-frame-rate-limit"],
  "all-stages": ["--run-all-compositor-stages-before-draw"],
};

function option(name, fallback) {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : fallback;
}
// The page (the first .html argument); in --ceiling mode further .html arguments are other
// builds of it, measured in the same rounds (before and after a change, interleaved).
const files = process.argv.slice(2).filter((a) => a.endsWith(".html")).map((a) => path.resolve(a));
if (!files.length) files.push(path.resolve("build/web/chainbreak.html"));
const file = files[0];

async function launch(extra) {
  return chromium.launch({ executablePath: "/usr/bin/chromium", args: baseArgs.concat(extra) });
}

// ---- the physics and the playing page (the default mode) ----
async function physicsAndFrames() {
  const browser = await launch([]);
  const page = await browser.newPage();
  await page.goto("file://" + file);
  await page.evaluate(() => window.chainbreak.ready);
  for (const beads of [1000, 100000]) {
    const result = await page.evaluate(async (n) => {
      const cb = window.chainbreak;
      // An unbreakable ramp, so every step is a plain step of the whole chain.
      cb.load(`[chain]\nbeads = ${n}\ngamma = 0.0\n[drive]\ntype = "ramp"\nbeta = 0.001\n` +
              `[integrator]\ndt = 0.01\nt_end = 100000.0\n`);
      let t0 = performance.now();
      const tau = n >= 100000 ? 2 : 50;
      await cb.runTo(tau);
      const physicsMs = performance.now() - t0;
      const steps = Math.round(tau / 0.01);
      // Frames: what one animation frame costs beyond the physics (snapshot, draw, blit),
      // and the browser's own frame rate with the page playing at 10 tau/s.
      const frames = 30;
      t0 = performance.now();
      for (let i = 0; i < frames; ++i) await cb.runTo(tau + (i + 1) * 1e-9);
      const frameMs = (performance.now() - t0) / frames;
      cb.play();
      let count = 0;
      const start = performance.now();
      await new Promise((done) => {
        const tick = () => { ++count; if (performance.now() - start < 3000) requestAnimationFrame(tick); else done(); };
        requestAnimationFrame(tick);
      });
      const fps = count / ((performance.now() - start) / 1000);
      const tauPerS = (cb.state().tau - tau) / ((performance.now() - start) / 1000);
      cb.pause();
      return { steps_per_s: steps / (physicsMs / 1000), bead_steps_per_s: n * steps / (physicsMs / 1000), frame_ms: frameMs, fps, tau_per_s: tauPerS };
    }, beads);
    console.log(`N = ${beads}: physics ${result.steps_per_s.toFixed(0)} steps/s (${(result.bead_steps_per_s / 1e6).toFixed(1)} M bead-steps/s); ` +
                `one frame's snapshot + draw ${result.frame_ms.toFixed(1)} ms; playing: ${result.fps.toFixed(1)} frames/s at ${result.tau_per_s.toFixed(2)} tau/s`);
  }
  await browser.close();
}

// ---- the ceiling ----
// Counts animation frames for `ms` in the page: frames/s, the median and 90th-percentile
// interval, and the page's own time per frame inside rAF callbacks (`busy`, from `window.__busy`
// if the case keeps it).
function countFrames(ms) {
  return new Promise((done) => {
    const times = [];
    const tick = (t) => {
      times.push(t);
      if (t - times[0] < ms) requestAnimationFrame(tick);
      else {
        const gaps = times.slice(1).map((x, i) => x - times[i]).sort((a, b) => a - b);
        const q = (p) => gaps[Math.min(gaps.length - 1, Math.floor(p * gaps.length))];
        done({ fps: gaps.length / ((times[times.length - 1] - times[0]) / 1000), median_ms: q(0.5), p90_ms: q(0.9) });
      }
    };
    requestAnimationFrame(tick);
  });
}

// A page with one WebGL2 canvas of the page's canvas's backing and CSS size, cleared to a new
// colour every frame (so every frame has something to present); `blit` also draws through an
// off-screen RGBA8 framebuffer of the same size, as page_bindings.cpp's draw did before
// session 10; `text` also changes a line of text above it every frame, as the page's status.
function glPage(size, attributes, blit, text) {
  return `<!DOCTYPE html><html><body style="margin:0">
<p id="t">τ = 0</p>
<canvas id="c" width="${size.width}" height="${size.height}"
        style="width:${size.cssWidth}px;height:${size.cssHeight}px;display:block"></canvas>
<script>
const c = document.getElementById("c");
const gl = c.getContext("webgl2", ${JSON.stringify(attributes)});
let fbo = null;
if (${blit}) {
  fbo = gl.createFramebuffer();
  gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
  const rb = gl.createRenderbuffer();
  gl.bindRenderbuffer(gl.RENDERBUFFER, rb);
  gl.renderbufferStorage(gl.RENDERBUFFER, gl.RGBA8, c.width, c.height);
  gl.framebufferRenderbuffer(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.RENDERBUFFER, rb);
}
let k = 0;
function frame() {
  ++k;
  if (${!!text}) document.getElementById("t").textContent = "τ = " + (k / 60).toFixed(2);
  gl.bindFramebuffer(gl.FRAMEBUFFER, fbo);
  gl.clearColor((k % 60) / 60, 0.5, 0.25, 1);
  gl.clear(gl.COLOR_BUFFER_BIT);
  if (fbo) {
    gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, null);
    gl.blitFramebuffer(0, 0, c.width, c.height, 0, 0, c.width, c.height, gl.COLOR_BUFFER_BIT, gl.NEAREST);
  }
  requestAnimationFrame(frame);
}
requestAnimationFrame(frame);
</script></body></html>`;
}

// Our page's WebGL context as page_bindings.cpp asked for it before session 10 (Emscripten's
// defaults otherwise: depth on, stencil off, premultiplied alpha), and as it asks now.
const ourAttributes = { alpha: false, antialias: false, depth: true, stencil: false,
                        premultipliedAlpha: true, preserveDrawingBuffer: false };
const ourAttributesNoDepth = Object.assign({}, ourAttributes, { depth: false });

const unbreakable = (n) => `[chain]\nbeads = ${n}\ngamma = 0.0\n[drive]\ntype = "ramp"\nbeta = 0.001\n` +
                           `[integrator]\ndt = 0.01\nt_end = 100000.0\n`;

// Each case: opens what it measures in `page` and returns extra numbers (or nothing).
function ceilingCases(size) {
  const html = (text) => async (page) => { await page.setContent(text); };
  // `from`: the tau to run to before playing; late in a run the plots hold their full
  // histories (2048 samples a curve, 512 rows of the space-time picture).
  const ours = (which, beads, from) => async (page) => {
    await page.goto("file://" + which);
    await page.evaluate(() => window.chainbreak.ready);
    if (beads) {
      await page.evaluate(async ([toml, tau]) => {
        window.chainbreak.load(toml);
        if (tau) await window.chainbreak.runTo(tau);
        window.chainbreak.play();
      }, [unbreakable(beads), from || 0]);
    }
  };
  const css = { width: Math.round(size.cssWidth), height: Math.round(size.cssHeight),
                cssWidth: size.cssWidth, cssHeight: size.cssHeight };
  const cases = {
    empty: html("<!DOCTYPE html><html><body><p>empty</p></body></html>"),
    text: html(`<!DOCTYPE html><html><body><p id="t"></p><script>let k = 0; const f = () => {
      document.getElementById("t").textContent = "τ = " + (++k / 60).toFixed(2); requestAnimationFrame(f); };
      requestAnimationFrame(f);</script></body></html>`),
    gl_default: html(glPage(size, {}, false)),
    gl_ours: html(glPage(size, ourAttributes, false)),
    gl_ours_blit: html(glPage(size, ourAttributes, true)),
    gl_ours_nodepth: html(glPage(size, ourAttributesNoDepth, false)),
    gl_ours_text: html(glPage(size, ourAttributes, false, true)),
    gl_ours_css: html(glPage(css, ourAttributes, false)),        // backing = CSS size
    gl_ours_blit_css: html(glPage(css, ourAttributes, true)),
  };
  files.forEach((f, i) => {
    const tag = files.length > 1 ? String.fromCharCode(65 + i) + "_" : "";  // A_, B_, ...
    cases[tag + "page_idle"] = ours(f, 0);
    cases[tag + "page_1000"] = ours(f, 1000);
    cases[tag + "page_1e5"] = ours(f, 100000);
    cases[tag + "page_1000_late"] = ours(f, 1000, 800);
  });
  return cases;
}

const median = (xs) => { const s = xs.slice().sort((a, b) => a - b); return s[Math.floor(s.length / 2)]; };

async function ceiling() {
  const rounds = Number(option("--rounds", 5));
  const seconds = Number(option("--seconds", 3));
  const flagNames = option("--flags", "default");
  const names = flagNames === "all" ? Object.keys(controlFlags) : flagNames.split(",");
  // The canvas's backing and CSS size in our page at the bench's viewport (Playwright's
  // default, 1280x720, device pixel ratio 1).
  let size;
  {
    const browser = await launch([]);
    const page = await browser.newPage();
    await page.goto("file://" + file);
    await page.evaluate(() => window.chainbreak.ready);
    size = await page.evaluate(() => {
      const c = document.getElementById("chain"), r = c.getBoundingClientRect();
      return { width: c.width, height: c.height, cssWidth: r.width, cssHeight: r.height,
               dpr: window.devicePixelRatio, viewport: [innerWidth, innerHeight] };
    });
    await browser.close();
  }
  console.log(`canvas ${size.width}x${size.height} shown at ${size.cssWidth.toFixed(1)}x${size.cssHeight.toFixed(1)} CSS px, ` +
              `devicePixelRatio ${size.dpr}, viewport ${size.viewport.join("x")}`);
  const cases = ceilingCases(size);
  files.forEach((f, i) => console.log(`${files.length > 1 ? String.fromCharCode(65 + i) + ": " : "page: "}${f}`));
  const only = option("--cases", "");
  // A name without its A_/B_ prefix picks that case for every page given.
  const caseNames = only ? Object.keys(cases).filter((c) => only.split(",").some((o) => c === o || c.endsWith("_" + o) && /^[A-Z]_/.test(c))) : Object.keys(cases);
  for (const name of names) {
    const browser = await launch(controlFlags[name]);
    const results = {};
    for (let r = 0; r < rounds; ++r) {
      for (const c of caseNames) {
        const page = await browser.newPage();
        await cases[c](page);
        await page.waitForTimeout(500);  // past the first frames' shader compiles and loads
        const tau0 = await page.evaluate(() => (window.chainbreak ? window.chainbreak.state().tau : 0)).catch(() => 0);
        const res = await page.evaluate(countFrames, seconds * 1000);
        const tau1 = await page.evaluate(() => (window.chainbreak ? window.chainbreak.state().tau : 0)).catch(() => 0);
        res.tau_per_s = (tau1 - tau0) / seconds;  // about: the window is measured in the page
        (results[c] = results[c] || []).push(res);
        await page.close();
      }
    }
    console.log(`flags: ${name} (${controlFlags[name].join(" ") || "none beyond SwiftShader's"}), medians of ${rounds} windows of ${seconds} s`);
    for (const c of caseNames) {
      const rs = results[c];
      const fps = rs.map((x) => x.fps);
      console.log(`  ${c.padEnd(13)} ${median(fps).toFixed(1).padStart(5)} frames/s ` +
                  `(range ${Math.min(...fps).toFixed(1)}-${Math.max(...fps).toFixed(1)}), frame interval median ` +
                  `${median(rs.map((x) => x.median_ms)).toFixed(1)} ms, p90 ${median(rs.map((x) => x.p90_ms)).toFixed(1)} ms` +
                  (/page_1/.test(c) ? `, ${median(rs.map((x) => x.tau_per_s)).toFixed(2)} tau/s` : ""));
    }
    await browser.close();
  }
}

(process.argv.includes("--ceiling") ? ceiling() : physicsAndFrames()).catch((e) => {
  console.error(e);
  process.exit(1);
});

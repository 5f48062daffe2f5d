// Speed of the page in headless Chromium on SwiftShader (no GPU): physics steps per second and
// frame times (snapshot + render + blit), apart, for N = 1000 and N = 1e5 (issue #25's goals:
// N = 1000 at 60 frames/s and 10 tau/s; N = 1e5 at >= 30 frames/s). Not a ctest: a measurement,
// recorded in the README ("In the browser"). Usage: node tests/web/bench_page.js build/web/chainbreak.html
"use strict";
const path = require("node:path");
const { chromium } = require("playwright-core");

(async () => {
  const file = path.resolve(process.argv[2] || "build/web/chainbreak.html");
  const browser = await chromium.launch({
    executablePath: "/usr/bin/chromium", args: ["--enable-unsafe-swiftshader", "--use-angle=swiftshader"] });
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
})();

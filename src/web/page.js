// The page's wiring: HTML controls -> the C++ module (page_bindings.cpp) and back. No physics,
// scene rule or drawing here (STYLE.md, "The web page"): values go to the program's scene
// reader as `--set` strings, errors come back as its messages, frames are drawn by its renderer.
"use strict";
(function () {
  const $ = (id) => document.getElementById(id);
  const canvas = $("chain");
  let page = null;  // the module's Page
  let Module = null;
  let playing = false;
  let clock = 0;  // the tau the run is heading for (wall time x speed); the physics lands on steps
  let lastTime = null;
  let announced = 0;  // breaks already announced
  let dirty = true;
  let presetId = "";
  // The physics gets at most this much of a frame; a chain too long for the speed asked for
  // falls behind (the status says by how much) instead of dropping the frame rate.
  const physicsBudgetMs = 12;
  let stepsPerMs = 50;  // measured as the run goes
  let behind = 1;       // achieved / requested speed over the last frame
  let hasGl = false;    // whether the canvas got its WebGL2 context

  const scenesDir = "/scenes";
  // The paper's three regimes and the one-body pull-or-jerk first, then the rest by name.
  const firstPresets = ["fast_pull", "slow_pull", "slower_pull", "ball_jerk", "ball_pull"];

  function fail(message) {
    const e = $("gl-error");
    e.textContent = message;
    e.hidden = false;
  }

  // ---- presets: every shipped scene, read from the module's copy of scenes/ ----
  function presetPaths() {
    const out = {};
    const walk = (dir) => {
      for (const name of Module.FS.readdir(dir)) {
        if (name === "." || name === "..") continue;
        const path = dir + "/" + name;
        if (Module.FS.isDir(Module.FS.stat(path).mode)) walk(path);
        else if (name.endsWith(".toml")) out[name.slice(0, -5)] = path;
      }
    };
    walk(scenesDir);
    return out;
  }
  let presets = {};

  function fillPresets() {
    presets = presetPaths();
    const ids = Object.keys(presets).sort((a, b) => {
      const ia = firstPresets.indexOf(a), ib = firstPresets.indexOf(b);
      if (ia >= 0 || ib >= 0) return (ia < 0 ? 99 : ia) - (ib < 0 ? 99 : ib);
      return a < b ? -1 : 1;
    });
    const select = $("preset");
    select.textContent = "";
    for (const id of ids) {
      const option = document.createElement("option");
      option.value = id;
      const text = Module.FS.readFile(presets[id], { encoding: "utf8" });
      const title = page.titleOf(text, presets[id]);
      option.textContent = title ? title + " (" + id + ")" : id;
      select.appendChild(option);
    }
    const custom = document.createElement("option");
    custom.value = "";
    custom.textContent = "(a scene file you opened)";
    custom.disabled = true;
    select.appendChild(custom);
  }

  // ---- scenes ----
  // Loads a scene's text through the program's reader with `--set` overrides [[key, value]].
  // Returns "" or the reader's message; on an error nothing changes.
  function loadText(text, path, overrides) {
    const lines = (overrides || []).map(([k, v]) => k + "=" + v).join("\n");
    const error = page.load(text, path, lines);
    if (!error) {
      // The scene's own view (a hanging chain hangs, issue #22); a field's edit keeps the
      // reader's choice, only a newly loaded scene resets it.
      $("view").value = page.scene().view || "longitudinal";
      restarted();
    }
    return error;
  }
  function loadPreset(id, overrides) {
    if (!(id in presets))
      return "scene=" + id + ": no shipped scene of that name; choose one of " +
             Object.keys(presets).sort().join(", ");
    const text = Module.FS.readFile(presets[id], { encoding: "utf8" });
    const error = loadText(text, presets[id], overrides);
    if (!error) {
      presetId = id;
      $("preset").value = id;
      updateLink();
    }
    return error;
  }

  function restarted() {
    clock = 0;
    announced = 0;
    $("breaks").textContent = "";
    $("announce").textContent = "";
    showScene();
    dirty = true;
  }

  function restart() {
    page.restart();
    restarted();
  }

  // ---- values shown with their symbols, and in SI units where the scene has [units] ----
  function fmt(x) {
    return Number.isFinite(x) ? String(Number(x.toPrecision(6))) : String(x);
  }
  function siOf(key, s) {
    const u = s.units;
    if (!u) return "";
    switch (key) {
      case "chain.gamma": return "Γ = " + fmt(s.gamma * u.gamma_scale) + " kg/s";
      case "chain.threshold": return "stretch " + fmt(s.threshold * u.length) + " m";
      case "drive.beta": return fmt(s.beta * u.force_scale * u.omega0) + " N/s";
      case "drive.amplitude": return fmt(s.amplitude * u.force_scale) + " N";
      case "drive.period": return fmt(s.period / u.omega0) + " s";
      default: return "";
    }
  }
  function tauText(tau, s) {
    let text = "τ = " + tau.toFixed(2);
    if (s.units) text += " (t = " + fmt(tau / s.units.omega0) + " s)";
    return text;
  }

  function showScene() {
    const s = page.scene();
    $("scene-title").textContent = s.title || s.name;
    document.title = (s.title || s.name) + " · chainbreak";
    const values = {
      "chain.beads": s.beads, "chain.gamma": s.gamma,
      "chain.threshold": Number.isFinite(s.threshold) ? s.threshold : "",
      "chain.break_on": s.break_on, "drive.type": s.drive, "drive.beta": s.beta,
      "drive.amplitude": s.amplitude, "drive.period": s.period, "drive.expr": s.expr,
    };
    for (const el of document.querySelectorAll("[data-key]")) {
      const key = el.dataset.key;
      el.value = values[key];
      el.removeAttribute("aria-invalid");
      const error = $(el.id + "-error");
      if (error) error.textContent = "";
      const si = el.parentElement.querySelector(".si");
      if (si) si.textContent = siOf(key, s);
    }
    for (const row of document.querySelectorAll("[data-drive]"))
      row.hidden = !row.dataset.drive.split(" ").includes(s.drive);
    $("zeta").textContent = s.drive === "ramp" && Number.isFinite(s.threshold)
      ? "ζ_c = φ_c / β = " + fmt(s.threshold / s.beta) : "";
    $("preset").value = presetId;
    updateLink();
  }

  // ---- the run ----
  function speed() {
    return Math.pow(10, Number($("speed").value));
  }
  function setPlaying(on) {
    playing = on && !page.atEnd();
    $("play").textContent = playing ? "Pause" : "Play";
    $("play").setAttribute("aria-pressed", String(playing));
    lastTime = null;
  }
  function advanceTo(tau) {
    clock = Math.max(clock, tau);
    if (!page.advanceTo(page.stepAt(clock))) {
      setPlaying(false);
      $("scene-error").textContent = page.error();
    }
    if (page.atEnd()) setPlaying(false);
    announceBreaks();
    dirty = true;
  }
  function stepOnce() {
    setPlaying(false);
    advanceTo(page.tau() + Math.max(page.dt(), speed() / 60));
  }

  function announceBreaks() {
    const breaks = page.breaks();
    if (breaks.length === announced) return;
    const s = page.scene();
    const lines = [];
    for (let i = announced; i < breaks.length; ++i) {
      const b = breaks[i];
      const what = b.spring === 0 ? "the pull string" : "spring " + b.spring;
      const line = what + " broke at " + tauText(b.tau, s);
      lines.push(line);
      const item = document.createElement("li");
      item.textContent = line;
      $("breaks").appendChild(item);
    }
    announced = breaks.length;
    $("announce").textContent = lines.join("; ");
  }

  function effectiveTheme() {
    const choice = $("theme").value;
    if (choice !== "auto") return choice;
    return window.matchMedia("(prefers-color-scheme: dark)").matches ? "dark" : "light";
  }
  function applyTheme() {
    document.documentElement.dataset.theme = effectiveTheme();
    dirty = true;
  }

  function draw() {
    // Without WebGL2 the physics still runs and the status, plots' numbers and announcements
    // follow it; initGl's message (why, and which browsers to try) stays in place.
    if (hasGl) {
      const error = page.draw(canvas.width, canvas.height, effectiveTheme(), $("view").value,
                              $("plots").checked);
      if (error) fail(error);
    }
    $("status").textContent = tauText(page.tau(), page.scene()) +
      (page.atEnd() ? " (end of the run)" : "") +
      (playing && behind < 0.95 ? " (behind: ×" + behind.toFixed(2) + " of the speed asked for)" : "");
    dirty = false;
  }

  function frame(time) {
    if (playing) {
      const wall = lastTime === null ? 0 : Math.min(0.1, (time - lastTime) / 1000);
      let rate = speed();
      const first = page.firstBreakTau();
      const s = page.scene();
      if ($("slowmo").checked && first >= 0 && Math.abs(clock - first) < s.slowmo_window)
        rate *= s.slowmo < 1 ? s.slowmo : 0.2;
      const wanted = clock + rate * wall;
      const from = page.step();
      const budget = page.tau() + Math.max(1, stepsPerMs * physicsBudgetMs) * page.dt();
      const start = performance.now();
      advanceTo(Math.min(wanted, budget));
      const spent = performance.now() - start, done = page.step() - from;
      if (done > 0 && spent > 0.5) stepsPerMs = 0.7 * stepsPerMs + 0.3 * (done / spent);
      behind = wanted > budget && rate * wall > 0 ? (budget - (wanted - rate * wall)) / (rate * wall) : 1;
      clock = Math.min(clock, page.tau() + page.dt());
      lastTime = time;
    }
    if (dirty) draw();
    requestAnimationFrame(frame);
  }

  // ---- the link: ?scene=NAME&key=value..., exactly as --set ----
  function linkOf() {
    const params = new URLSearchParams();
    if (presetId) params.set("scene", presetId);
    for (const [k, v] of page.overrides()) params.set(k, v);
    if ($("theme").value !== "auto") params.set("render.theme", $("theme").value);
    if ($("view").value !== "longitudinal") params.set("render.view", $("view").value);
    const base = location.href.split("?")[0].split("#")[0];
    return base + "?" + params.toString();
  }
  function updateLink() {
    $("link").value = linkOf();
  }

  function fromUrl() {
    const params = new URLSearchParams(location.search);
    const id = params.get("scene") || "anomalous_breaking";
    const overrides = [];
    for (const [k, v] of params) if (k !== "scene") overrides.push([k, v]);
    let error = loadPreset(id, overrides);
    if (error) {
      $("scene-error").textContent = "In the link: " + error;
      // Never a blank page: the default scene instead.
      const fallback = loadPreset("anomalous_breaking", []);
      if (fallback) fail(fallback);
    } else {
      for (const [k, v] of overrides) {
        if (k === "render.theme") $("theme").value = v;
        if (k === "render.view") $("view").value = v;
      }
    }
  }

  // ---- files ----
  function download(blob, name) {
    const a = document.createElement("a");
    a.href = URL.createObjectURL(blob);
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(a.href), 1000);
  }
  function openFile(file) {
    file.text().then((text) => {
      const error = loadText(text, file.name, []);
      $("scene-error").textContent = error;
      if (!error) {
        presetId = "";
        showScene();
      }
    });
  }

  function wire() {
    $("preset").addEventListener("change", () => {
      const error = loadPreset($("preset").value, []);
      $("scene-error").textContent = error;
    });
    $("open").addEventListener("change", () => {
      if ($("open").files.length) openFile($("open").files[0]);
    });
    document.addEventListener("dragover", (e) => e.preventDefault());
    document.addEventListener("drop", (e) => {
      e.preventDefault();
      if (e.dataTransfer.files.length) openFile(e.dataTransfer.files[0]);
    });
    for (const el of document.querySelectorAll("[data-key]")) {
      el.addEventListener("change", () => {
        // An expression drive needs its expression: a scene of another kind gets a slow ramp's
        // to start from, which the field then shows (a failed set changes nothing).
        if (el.dataset.key === "drive.type" && el.value === "expr" && !page.scene().expr)
          page.set("drive.expr", "0.02*t");
        const error = page.set(el.dataset.key, el.value === "" ? "nan" : el.value);
        const out = $(el.id + "-error");
        if (error) {
          out.textContent = error;
          el.setAttribute("aria-invalid", "true");
        } else {
          restarted();
        }
      });
    }
    $("play").addEventListener("click", () => setPlaying(!playing));
    $("step").addEventListener("click", stepOnce);
    $("restart").addEventListener("click", () => { setPlaying(false); restart(); });
    $("speed").addEventListener("input", () => {
      $("speed-value").textContent = fmt(speed());
    });
    $("view").addEventListener("change", () => { dirty = true; updateLink(); });
    $("plots").addEventListener("change", () => { dirty = true; });
    $("theme").addEventListener("change", () => { applyTheme(); updateLink(); });
    window.matchMedia("(prefers-color-scheme: dark)").addEventListener("change", applyTheme);
    $("copy-link").addEventListener("click", () => {
      const link = linkOf();
      $("link").value = link;
      const done = () => { $("share-status").textContent = "Link copied."; };
      const manual = () => {
        $("link").select();
        $("share-status").textContent = "Select the link above and copy it (Ctrl+C).";
      };
      if (navigator.clipboard) navigator.clipboard.writeText(link).then(done, manual);
      else manual();
    });
    $("save-toml").addEventListener("click", () => {
      download(new Blob([page.toml()], { type: "text/plain" }), page.scene().name + ".toml");
      $("share-status").textContent = "Scene saved as " + page.scene().name + ".toml.";
    });
    $("save-png").addEventListener("click", () => {
      draw();
      const name = page.scene().name + "_tau_" + page.tau().toFixed(3) + ".png";
      canvas.toBlob((blob) => {
        download(blob, name);
        $("share-status").textContent = "Snapshot saved as " + name + ".";
      }, "image/png");
    });
    document.addEventListener("keydown", (e) => {
      if (e.altKey || e.ctrlKey || e.metaKey) return;
      const tag = e.target && e.target.tagName;
      const formControl = tag === "INPUT" || tag === "SELECT" || tag === "TEXTAREA" ||
                          tag === "BUTTON" || tag === "A";
      if (formControl) return;  // their own keys (Space presses a button, arrows move a slider)
      if (e.key === " ") { setPlaying(!playing); e.preventDefault(); }
      else if (e.key === "ArrowRight") { stepOnce(); e.preventDefault(); }
      else if (e.key === "ArrowLeft") { setPlaying(false); restart(); e.preventDefault(); }
    });
  }

  // ---- the test API (README, "In the browser") ----
  function state() {
    return { tau: page.tau(), playing, beads: page.scene().beads, breaks: page.breaks(),
             energy: page.energy() };
  }
  function check(error) {
    if (error) throw new Error(error);
  }
  const api = {
    load(toml) { check(loadText(String(toml), "scene.toml", [])); presetId = ""; showScene(); },
    set(key, value) { check(page.set(String(key), String(value))); restarted(); },
    play() { setPlaying(true); },
    pause() { setPlaying(false); },
    runTo(tau) {
      advanceTo(Number(tau));
      draw();
      return Promise.resolve(state());
    },
    state,
    // What the tests compare with `chainbreak snapshot`: the frame drawn now, RGBA rows
    // top-down, and its size.
    pixels() {
      draw();
      return { width: canvas.width, height: canvas.height, rgba: Array.from(page.pixels()) };
    },
  };

  api.ready = createChainbreakModule({
    preRun: [(m) => { m.ENV.CHAINBREAK_FONT_DIR = "/fonts"; }],
    print: (text) => console.log(text),
    printErr: (text) => console.warn(text),
  }).then((m) => {
    Module = m;
    page = new m.Page();
    const glError = page.initGl();
    hasGl = !glError;
    if (glError) fail(glError);
    fillPresets();
    wire();
    $("speed-value").textContent = fmt(speed());
    applyTheme();
    fromUrl();
    requestAnimationFrame(frame);
    return api;
  }, (error) => {
    fail("The simulator did not start: " + error);
    throw error;
  });
  window.chainbreak = api;
})();

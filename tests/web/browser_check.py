#!/usr/bin/env python3
"""The page in Firefox and in WebKit (issue #25: "current Chromium, Firefox and Safari").

Chromium is tested by playwright-core (page_tests.js). For the other two this drives the browser
through its own remote protocol and, for each scene, opens build/web/chainbreak.html?scene=NAME
from file://, runs it to the end with window.chainbreak.runTo, and compares the breaks with
`chainbreak run` (spring and tau, the same doubles); it reports whether the canvas got WebGL2
and saves a screenshot of the last scene.

- firefox: Debian's firefox-esr through Marionette (JSON messages framed as "length:payload"
  over TCP): Playwright's Firefox speaks WebDriver BiDi commands that firefox-esr does not know.
- webkit: WebKitGTK, Safari's engine (JavaScriptCore, WebKit's WebGL2; its user agent says
  Safari/605.1.15), through WebKitWebDriver (W3C WebDriver over HTTP) and its MiniBrowser. Not
  Safari itself, which needs macOS, but the engine that decides whether the page runs in it.

    apt-get install -y webkit2gtk-driver     # in the README's install line: the ctest web_webkit
    apt-get install -y firefox-esr           # not in the install line: by hand only
    xvfb-run -a -s "-screen 0 1400x1000x24" /usr/bin/python3 tests/web/browser_check.py \\
        --browser webkit build/web/chainbreak.html build/chainbreak scenes

Firefox runs headless unless --display is given (headless Firefox has no WebGL2 without a GPU;
the breaks are still compared and the page shows why it draws nothing); WebKitGTK always needs
a display (Xvfb).
"""
import argparse
import base64
import json
import os
import pathlib
import shutil
import socket
import subprocess
import sys
import tempfile
import time
import urllib.error
import urllib.request

SCENES = ["anomalous_breaking", "ramp_pulled_end", "step_pulse", "two_impulses", "table_drive",
          "expr_drive", "fast_pull", "flawed_chain", "two_materials", "weak_link", "hanging_chain"]
TIMEOUT_MS = 300000


def wait_for(connect, what):
    for _ in range(150):
        try:
            return connect()
        except OSError:
            time.sleep(0.2)
    raise RuntimeError(f"no {what}")


class Marionette:
    """Firefox's remote protocol: commands as [0, id, name, params]."""

    def __init__(self, args):
        firefox = shutil.which("firefox-esr") or shutil.which("firefox")
        if not firefox:
            sys.exit("browser_check: no firefox-esr (apt-get install -y firefox-esr)")
        self.version = subprocess.run([firefox, "--version"], capture_output=True,
                                      text=True).stdout.strip()
        self.profile = tempfile.mkdtemp(prefix="chainbreak_ff_")
        port = 2828 + os.getpid() % 1000
        pathlib.Path(self.profile, "user.js").write_text(f'user_pref("marionette.port", {port});\n')
        command = [firefox, "--marionette", "--profile", self.profile, "--window-size", "1280,900"]
        if not args.display:
            command.insert(1, "--headless")
        self.process = subprocess.Popen(command, stdout=subprocess.DEVNULL,
                                        stderr=subprocess.DEVNULL)
        self.sock = wait_for(lambda: socket.create_connection(("127.0.0.1", port)), "Marionette")
        self.buffer = b""
        self.last_id = 0
        self._read()  # the server's greeting
        self._command("WebDriver:NewSession", {"capabilities": {}})
        self._command("WebDriver:SetTimeouts", {"script": TIMEOUT_MS})

    def _read(self):
        while b":" not in self.buffer:
            self.buffer += self.sock.recv(1 << 16)
        length, rest = self.buffer.split(b":", 1)
        while len(rest) < int(length):
            rest += self.sock.recv(1 << 20)
        self.buffer = rest[int(length):]
        return json.loads(rest[: int(length)])

    def _command(self, name, params):
        self.last_id += 1
        data = json.dumps([0, self.last_id, name, params]).encode()
        self.sock.sendall(str(len(data)).encode() + b":" + data)
        _, _, error, result = self._read()
        if error:
            raise RuntimeError(f"{name}: {error}")
        return result

    def navigate(self, url):
        self._command("WebDriver:Navigate", {"url": url})

    def run_async(self, script):
        return self._command("WebDriver:ExecuteAsyncScript", {"script": script, "args": []})["value"]

    def screenshot(self):
        return base64.b64decode(self._command("WebDriver:TakeScreenshot", {"full": False})["value"])

    def close(self):
        try:
            self._command("WebDriver:DeleteSession", {})
        finally:
            self.process.kill()
            shutil.rmtree(self.profile, ignore_errors=True)


class WebKitDriver:
    """W3C WebDriver over HTTP, served by WebKitGTK's WebKitWebDriver, driving MiniBrowser."""

    MINIBROWSER = "/usr/lib/x86_64-linux-gnu/webkit2gtk-4.1/MiniBrowser"

    def __init__(self, args):
        driver = shutil.which("WebKitWebDriver")
        if not driver or not os.path.exists(self.MINIBROWSER):
            sys.exit("browser_check: no WebKitWebDriver (apt-get install -y webkit2gtk-driver)")
        if not os.environ.get("DISPLAY"):
            sys.exit("browser_check: WebKitGTK needs a display; run under xvfb-run")
        self.port = 4444 + os.getpid() % 1000
        self.process = subprocess.Popen([driver, f"--port={self.port}"],
                                        stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        wait_for(lambda: self._request("GET", "/status"), "WebKitWebDriver")
        options = {"binary": self.MINIBROWSER, "args": ["--automation"]}
        session = self._request("POST", "/session", {"capabilities": {"alwaysMatch": {
            "webkitgtk:browserOptions": options}}})["value"]
        self.session = f"/session/{session['sessionId']}"
        caps = session["capabilities"]
        self.version = f"WebKitGTK {caps['browserVersion']} ({caps['browserName']})"
        self._request("POST", self.session + "/timeouts", {"script": TIMEOUT_MS})

    def _request(self, method, path, body=None):
        data = json.dumps(body).encode() if body is not None else None
        request = urllib.request.Request(f"http://127.0.0.1:{self.port}{path}", data=data,
                                         method=method,
                                         headers={"Content-Type": "application/json"})
        try:
            with urllib.request.urlopen(request, timeout=TIMEOUT_MS / 1000 + 60) as reply:
                return json.loads(reply.read())
        except urllib.error.HTTPError as e:
            raise RuntimeError(f"{method} {path}: {e.read().decode(errors='replace')}") from e
        except urllib.error.URLError as e:  # not listening yet: wait_for retries
            raise OSError(str(e)) from e

    def navigate(self, url):
        self._request("POST", self.session + "/url", {"url": url})

    def run_async(self, script):
        return self._request("POST", self.session + "/execute/async",
                             {"script": script, "args": []})["value"]

    def screenshot(self):
        return base64.b64decode(self._request("GET", self.session + "/screenshot")["value"])

    def close(self):
        try:
            self._request("DELETE", self.session)
        finally:
            self.process.kill()


RUN_TO_END = """
const done = arguments[arguments.length - 1];
window.chainbreak.ready
  .then(() => window.chainbreak.runTo(1e300))
  .then((state) => done({state, webgl2: !!document.getElementById('chain').getContext('webgl2'),
                         message: document.getElementById('gl-error').textContent,
                         agent: navigator.userAgent}))
  .catch((e) => done({error: String(e) + (e && e.stack ? ' stack: ' + e.stack : '')}));
"""


# WebKitGTK 2.50.6 now and then fails a scene that passes on the next try: its wasm traps
# ("Out of bounds memory access") or its driver answers "Could not parse script result". Seen
# in 2 of 15 runs of this check on 2026-11-27, once in 30 on 2026-11-28, and in CI runs, on
# different scenes, never in Chromium's or Firefox's runs of the same page. We take it for the
# engine's: one trap's stack (2026-11-28; function names from a --profiling-funcs build of the
# same code) was Page::title_of -> parse_scene -> check_values -> rk4_stability_limit ->
# rk4_stable_step, at page start (fillPresets), before any frame or timer: the same wasm, inputs
# and memory in every run, in a function that touches only its own stack frame. The C++ under
# the page passes valgrind and ASan natively (tests/test_web_session.cpp). With JSC's optimizing
# tier off (JSC_useOMGJIT=false) 8 runs of 8 passed. WebKit gets a second try at a scene, printed
# with the error's stack when taken; both must fail to fail.
def run_scene(browser, args, name):
    url = pathlib.Path(args.page).resolve().as_uri() + "?scene=" + name
    tries = 2 if args.browser == "webkit" else 1
    for attempt in range(1, tries + 1):
        try:
            browser.navigate(url)
            got = browser.run_async(RUN_TO_END)
        except RuntimeError as e:  # the driver's error (HTTP 500)
            got = {"error": f"driver: {e}"}
        if "error" not in got or attempt == tries:
            return got
        print(f"{name}: try {attempt} failed ({got['error'][:4000]}); trying again")


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("page")
    parser.add_argument("exe")
    parser.add_argument("scenes")
    parser.add_argument("--browser", choices=["firefox", "webkit"], default="firefox")
    parser.add_argument("--display", action="store_true", help="firefox: run with a display")
    parser.add_argument("--require-webgl2", action="store_true",
                        help="fail when the canvas gets no WebGL2 context")
    parser.add_argument("--screenshot", default=None, help="default: BROWSER_page.png")
    args = parser.parse_args()
    scene_files = {p.stem: p for p in pathlib.Path(args.scenes).rglob("*.toml")}
    browser = (Marionette if args.browser == "firefox" else WebKitDriver)(args)
    failures = 0
    try:
        print(browser.version)
        for name in SCENES:
            got = run_scene(browser, args, name)
            if "error" in got:
                print(f"{name}: FAILED in the page: {got['error']}")
                failures += 1
                continue
            cli = json.loads(subprocess.run([args.exe, "run", str(scene_files[name]), "-q"],
                                            check=True, capture_output=True, text=True).stdout)
            page_breaks = [(b["spring"], b["tau"]) for b in got["state"]["breaks"]]
            cli_breaks = [(b["spring"], b["tau"]) for b in cli["breaks"]]
            same = page_breaks == cli_breaks
            failures += not same
            verdict = "the CLI's doubles" if same else "DIFFER from the CLI"
            webgl = "yes" if got["webgl2"] else f"no ({got['message']})"
            failures += args.require_webgl2 and not got["webgl2"]
            print(f"{name}: {len(page_breaks)} breaks, {verdict}; WebGL2 {webgl}")
        print(f"user agent: {got.get('agent', '?')}")
        shot = args.screenshot or f"{args.browser}_page.png"
        pathlib.Path(shot).write_bytes(browser.screenshot())
        print(f"screenshot of {SCENES[-1]}: {shot}")
    finally:
        browser.close()
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()

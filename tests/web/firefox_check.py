#!/usr/bin/env python3
"""The page in Firefox (issue #25: "current Chromium, Firefox and Safari"), by hand, not a ctest.

Playwright's Firefox speaks WebDriver BiDi commands that Debian's firefox-esr does not know yet,
so this drives Firefox through Marionette, its own remote protocol (JSON messages framed as
"length:payload" over TCP). For each scene it opens build/web/chainbreak.html?scene=NAME from
file://, runs it to the end with window.chainbreak.runTo, and compares the breaks with
`chainbreak run` (spring and tau, the same doubles); it reports whether the canvas got WebGL2
and saves a screenshot of the last scene.

    apt-get install -y firefox-esr          # not in the README's install line: not in CI
    xvfb-run -a -s "-screen 0 1400x1000x24" /usr/bin/python3 tests/web/firefox_check.py \\
        build/web/chainbreak.html build/chainbreak scenes --display

Without --display Firefox runs headless, where it gives no WebGL2 on a machine without a GPU:
the breaks are still compared and the page shows why it draws nothing.
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

SCENES = ["anomalous_breaking", "ramp_pulled_end", "step_pulse", "two_impulses", "table_drive",
          "expr_drive", "fast_pull", "flawed_chain", "two_materials", "weak_link", "hanging_chain"]


class Marionette:
    def __init__(self, port):
        for _ in range(150):
            try:
                self.sock = socket.create_connection(("127.0.0.1", port))
                break
            except OSError:
                time.sleep(0.2)
        else:
            raise RuntimeError(f"no Marionette on port {port}")
        self.buffer = b""
        self.last_id = 0
        self._read()  # the server's greeting

    def _read(self):
        while b":" not in self.buffer:
            self.buffer += self.sock.recv(1 << 16)
        length, rest = self.buffer.split(b":", 1)
        while len(rest) < int(length):
            rest += self.sock.recv(1 << 20)
        self.buffer = rest[int(length):]
        return json.loads(rest[: int(length)])

    def command(self, name, params):
        self.last_id += 1
        data = json.dumps([0, self.last_id, name, params]).encode()
        self.sock.sendall(str(len(data)).encode() + b":" + data)
        _, _, error, result = self._read()
        if error:
            raise RuntimeError(f"{name}: {error}")
        return result


RUN_TO_END = """
const done = arguments[arguments.length - 1];
window.chainbreak.ready
  .then(() => window.chainbreak.runTo(1e300))
  .then((state) => done({state, webgl2: !!document.getElementById('chain').getContext('webgl2'),
                         message: document.getElementById('gl-error').textContent}))
  .catch((e) => done({error: String(e)}));
"""


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("page")
    parser.add_argument("exe")
    parser.add_argument("scenes")
    parser.add_argument("--display", action="store_true", help="run with a display (Xvfb)")
    parser.add_argument("--screenshot", default="firefox_page.png")
    args = parser.parse_args()
    firefox = shutil.which("firefox-esr") or shutil.which("firefox")
    if not firefox:
        sys.exit("firefox_check: no firefox-esr (apt-get install -y firefox-esr)")
    scene_files = {p.stem: p for p in pathlib.Path(args.scenes).rglob("*.toml")}
    profile = tempfile.mkdtemp(prefix="chainbreak_ff_")
    port = 2828 + os.getpid() % 1000
    pathlib.Path(profile, "user.js").write_text(f'user_pref("marionette.port", {port});\n')
    command = [firefox, "--marionette", "--profile", profile, "--window-size", "1280,900"]
    if not args.display:
        command.insert(1, "--headless")
    browser = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    failures = 0
    try:
        m = Marionette(port)
        m.command("WebDriver:NewSession", {"capabilities": {}})
        m.command("WebDriver:SetTimeouts", {"script": 300000})
        print(subprocess.run([firefox, "--version"], capture_output=True, text=True).stdout.strip())
        for name in SCENES:
            m.command("WebDriver:Navigate",
                      {"url": pathlib.Path(args.page).resolve().as_uri() + "?scene=" + name})
            got = m.command("WebDriver:ExecuteAsyncScript", {"script": RUN_TO_END, "args": []})["value"]
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
            print(f"{name}: {len(page_breaks)} breaks, {verdict}; WebGL2 {webgl}")
        png = m.command("WebDriver:TakeScreenshot", {"full": False})["value"]
        pathlib.Path(args.screenshot).write_bytes(base64.b64decode(png))
        print(f"screenshot of {SCENES[-1]}: {args.screenshot}")
        m.command("WebDriver:DeleteSession", {})
    finally:
        browser.kill()
        shutil.rmtree(profile, ignore_errors=True)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()

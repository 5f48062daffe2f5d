#!/usr/bin/python3
"""The matplotlib baseline for `chainbreak render` (README.md, section Video).

The default scene (scenes/anomalous_breaking.toml: N = 30 beads, ramp f = 0.02 tau,
gamma = 0, phi_c = 3) animated the way a physics student would: the chain integrated with
numpy RK4, a matplotlib FuncAnimation drawing the same picture as `render` (dark
background, hatched wall, springs coloured by strain phi/phi_c, shaded beads, the force
arrow, tau, a colour bar), 1920x1080 (figsize 19.2 x 10.8 in at 100 dpi), saved with
matplotlib's FFMpegWriter: libx264, crf 18, the same preset and 2 threads as chainbreak's
encoder. Then, on the same clip (frames, size, fps, preset), the `chainbreak render`
process, as it is (with its overlay: HUD and plots under the chain, which the matplotlib
picture does not have) and with render.overlay = false (the same picture as matplotlib's);
all in frames/s, one after the other in one run.

The clip: the first --frames frames at 60 fps and 10 tau/s (tau 0 .. 39.8), the step
`render` uses, dt = (1/6)/17 (17 steps per frame). No spring breaks in it (the first break is
at tau ~ 150), so the script needs no breaking; it checks that max |phi| < phi_c.
With --chainbreak, the numpy chain is first checked against `chainbreak run` at the same dt.

Needs Debian's /usr/bin/python3 with python3-numpy, python3-matplotlib and the ffmpeg
program (FFMpegWriter runs it): apt-get install python3-matplotlib ffmpeg.

  /usr/bin/python3 tests/bench/matplotlib_baseline.py --chainbreak build/chainbreak
"""
import argparse
import csv
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
import matplotlib

matplotlib.use("Agg")  # headless, rasterises with Agg like savefig to a file
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib import animation  # noqa: E402
from matplotlib.collections import LineCollection  # noqa: E402
from matplotlib.colors import LinearSegmentedColormap  # noqa: E402
from matplotlib.patches import FancyArrow, Rectangle  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "..", "..", "scenes", "anomalous_breaking.toml")
N, BETA, GAMMA, PHI_C = 30, 0.02, 0.0, 3.0  # the scene's [chain] and [drive]
FPS, SPEED = 60, 10.0  # its [render]
SUBSTEPS = 17  # render_plan.cpp: ceil((SPEED / FPS) / 0.01)
DT = SPEED / FPS / SUBSTEPS


def accel(psi, vel, tau):
    """Eq. (dimless): psi_0 = 0 (wall), psi_{N+1} = psi_N (free end), f on bead N."""
    left = np.concatenate(([0.0], psi[:-1]))
    right = np.concatenate((psi[1:], psi[-1:]))
    a = left - 2.0 * psi + right - 2.0 * GAMMA * vel
    a[-1] += BETA * tau
    return a


def integrate(frames):
    """psi of every bead at every frame (frames x N), by classical RK4 at DT."""
    psi, vel = np.zeros(N), np.zeros(N)
    out = np.empty((frames, N))
    step = 0
    for k in range(frames):
        while step < k * SUBSTEPS:
            tau = step * DT
            h = 0.5 * DT
            k1x, k1v = vel, accel(psi, vel, tau)
            k2x, k2v = vel + h * k1v, accel(psi + h * k1x, vel + h * k1v, tau + h)
            k3x, k3v = vel + h * k2v, accel(psi + h * k2x, vel + h * k2v, tau + h)
            k4x, k4v = vel + DT * k3v, accel(psi + DT * k3x, vel + DT * k3v, tau + DT)
            psi = psi + DT / 6.0 * (k1x + 2 * k2x + 2 * k3x + k4x)
            vel = vel + DT / 6.0 * (k1v + 2 * k2v + 2 * k3v + k4v)
            step += 1
        out[k] = psi
    return out


def check_against_chainbreak(exe, psi):
    """The numpy chain is the program's chain: `chainbreak run` at the same dt, last frame."""
    steps = (len(psi) - 1) * SUBSTEPS
    with tempfile.TemporaryDirectory() as tmp:
        path = os.path.join(tmp, "run.csv")
        subprocess.run([exe, "run", SCENE, "--set", "integrator.dt=%r" % DT,
                        "--set", "integrator.t_end=%r" % (steps * DT), "--psi",
                        "--every", str(SUBSTEPS), "--csv", path, "--quiet"],
                       check=True, stdout=subprocess.DEVNULL)
        with open(path) as f:
            rows = list(csv.DictReader(f))
    last = np.array([float(rows[-1]["psi_%d" % j]) for j in range(1, N + 1)])
    err = np.max(np.abs(last - psi[-1])) / np.max(np.abs(psi[-1]))
    # Same RK4, same dt: only rounding and the program's step splitting differ.
    if len(rows) != len(psi) or err > 1e-9:
        sys.exit("numpy chain disagrees with chainbreak run: %d rows, relative error %.3g"
                 % (len(rows), err))
    return err


def make_animation(psi):
    """The FuncAnimation: one picture of the chain per frame, as `render` draws it."""
    frames = len(psi)
    psi_range = np.max(np.abs(psi))
    force_range = BETA * (frames - 1) * SUBSTEPS * DT
    fig = plt.figure(figsize=(19.2, 10.8), dpi=100, facecolor="#1a1b1f")
    ax = fig.add_axes([0.03, 0.25, 0.94, 0.6])
    ax.set_facecolor("#1a1b1f")
    ax.set_axis_off()
    ax.set_xlim(-1.5, N + psi_range + 4.0)
    ax.set_ylim(-3, 3)
    ax.add_patch(Rectangle((-0.8, -1.5), 0.8, 3.0, facecolor="#555", edgecolor="#ccc",
                           hatch="///"))
    # Diverging: compression dark blue, rest grey, tension light orange (lightness rising).
    cmap = LinearSegmentedColormap.from_list("strain",
                                             ["#2020c0", "#8a8a8a", "#d8a070", "#ffee60"])
    springs = LineCollection([], linewidths=4, cmap=cmap)
    springs.set_clim(-PHI_C, PHI_C)
    ax.add_collection(springs)
    beads = ax.scatter([], [], s=250, c="#c8c8d0", edgecolors="#f0f0f0", linewidths=1.5,
                       zorder=3)
    label = fig.text(0.01, 0.96, "", color="w", family="monospace", fontsize=20)
    arrow = [None]
    cax = fig.add_axes([0.3, 0.08, 0.4, 0.04])
    bar = fig.colorbar(springs, cax=cax, orientation="horizontal")
    bar.set_ticks([-PHI_C, 0, PHI_C], labels=["-phi_c = -3", "0", "+phi_c = 3"], color="w",
                  fontsize=16)
    fig.text(0.29, 0.09, "compression", color="w", ha="right", family="monospace", fontsize=16)
    fig.text(0.71, 0.09, "tension", color="w", family="monospace", fontsize=16)

    def update(k):
        x = np.arange(N + 1, dtype=float)
        x[1:] += psi[k]  # longitudinal view: bead j at j + psi_j; bead 0 is the wall
        phi = np.diff(np.concatenate(([0.0], psi[k])))
        springs.set_segments([[(x[j], 0), (x[j + 1], 0)] for j in range(N)])
        springs.set_array(phi)
        beads.set_offsets(np.column_stack((x[1:], np.zeros(N))))
        tau = k * SUBSTEPS * DT
        f = BETA * tau
        if arrow[0] is not None:
            arrow[0].remove()
        length = 3.0 * f / force_range + 1e-3  # as render: follows f, longest at the end
        arrow[0] = ax.add_patch(FancyArrow(x[-1] + 0.4, 0, length, 0, width=0.05,
                                           head_width=0.3, head_length=0.3, color="w"))
        label.set_text("tau = %.2f    f = %.2f" % (tau, f))
        return springs, beads, label, arrow[0]

    return fig, animation.FuncAnimation(fig, update, frames=frames, blit=False)


def time_render(exe, frames, preset, overlay):
    """`chainbreak render` on the same clip; seconds, wall clock."""
    t_end = (frames - 1 + 0.4) * SPEED / FPS  # floor(t_end / (1/6)) + 1 = frames
    with tempfile.TemporaryDirectory(dir="/dev/shm") as tmp:
        out = os.path.join(tmp, "anomalous_breaking.mp4")
        start = time.perf_counter()
        subprocess.run([exe, "render", SCENE, "-o", out, "--set", "integrator.t_end=%r" % t_end,
                        "--set", "render.overlay=%s" % ("true" if overlay else "false"),
                        "--preset", preset, "--quiet"],
                       check=True, stdout=subprocess.DEVNULL)
        seconds = time.perf_counter() - start
        with open(os.path.join(tmp, "anomalous_breaking.json")) as f:
            if json.load(f)["frames"] != frames:
                sys.exit("chainbreak rendered another number of frames")
    return seconds


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--chainbreak", help="the chainbreak program (else only matplotlib is timed)")
    ap.add_argument("--frames", type=int, default=240)
    ap.add_argument("--preset", default="veryfast")
    ap.add_argument("--json", help="write the results here")
    ap.add_argument("--keep", help="keep matplotlib's video here (default: a temporary file)")
    a = ap.parse_args()

    psi = integrate(a.frames)  # before timing: the animation is what is measured
    phi = np.diff(np.concatenate((np.zeros((a.frames, 1)), psi), axis=1), axis=1)
    assert np.max(np.abs(phi)) < PHI_C, "a spring would break inside the clip"
    result = {"frames": a.frames, "size": "1920x1080", "fps": FPS, "preset": a.preset,
              "matplotlib": matplotlib.__version__}
    if a.chainbreak:
        result["numpy_vs_chainbreak_rel_error"] = check_against_chainbreak(a.chainbreak, psi)

    fig, anim = make_animation(psi)
    writer = animation.FFMpegWriter(
        fps=FPS, codec="h264", extra_args=["-preset", a.preset, "-crf", "18", "-threads", "2"])
    with tempfile.TemporaryDirectory(dir="/dev/shm") as tmp:
        start = time.perf_counter()
        anim.save(a.keep or os.path.join(tmp, "matplotlib.mp4"), writer=writer, dpi=100)
        seconds = time.perf_counter() - start
    plt.close(fig)
    result["matplotlib_fps"] = a.frames / seconds
    print("%-42s %d frames in %.2f s, %.1f frames/s"
          % ("matplotlib FuncAnimation + FFMpegWriter:", a.frames, seconds, a.frames / seconds))
    if a.chainbreak:
        for key, overlay, what in (("chainbreak_fps", True, "with its overlay"),
                                   ("chainbreak_no_overlay_fps", False, "chain only")):
            seconds = time_render(a.chainbreak, a.frames, a.preset, overlay)
            result[key] = a.frames / seconds
            print("%-42s %d frames in %.2f s, %.1f frames/s (%.1f x matplotlib)"
                  % ("chainbreak render, %s:" % what, a.frames, seconds, a.frames / seconds,
                     result[key] / result["matplotlib_fps"]))
    if a.json:
        with open(a.json, "w") as f:
            json.dump(result, f, indent=1)


if __name__ == "__main__":
    main()

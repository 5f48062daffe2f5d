# `import chainbreak` and its run(), exact() and sweep() load none of the render stack (issue 13,
# like the CLI's run/sweep in tests/test_startup.cpp): snapshot() and render() open the picture
# module chainbreak-pictures.so on their first call (src/python/py_frames.cpp).
import os
import re
import subprocess
import sys

RENDER_STACK = re.compile(r"/(chainbreak-pictures|libavcodec|libavformat|libswscale|libcairo|"
                          r"libfreetype|libstb|libOSMesa|libEGL)[^/]*$")


def mapped_objects(code):
    """The files mapped into a fresh interpreter after it ran `code` (from /proc/self/maps)."""
    script = code + "\nimport sys\nsys.stdout.write(open('/proc/self/maps').read())\n"
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          env=os.environ, check=False)
    assert done.returncode == 0, done.stderr
    return {line.split()[-1] for line in done.stdout.splitlines() if "/" in line}


def test_run_and_sweep_load_no_render_stack(scenes):
    objects = mapped_objects(f"""
import chainbreak
scene = chainbreak.Scene.load({str(scenes / "step_pulse.toml")!r})
scene.set("integrator.t_end", 1.0)
chainbreak.run(scene)
chainbreak.sweep(scene, vary={{"drive.amplitude": [0.5, 1.0]}}, solver="exact")
""")
    assert any("libchainbreak-core" in o for o in objects)  # not vacuous: the core is there
    assert sorted(o for o in objects if RENDER_STACK.search(o)) == []


def test_snapshot_opens_the_picture_module(scenes):
    objects = mapped_objects(f"""
import chainbreak
scene = chainbreak.Scene.load({str(scenes / "step_pulse.toml")!r})
chainbreak.snapshot(scene, 0.0, size=(64, 48))
""")
    assert any(o.endswith("/chainbreak-pictures.so") for o in objects)
    assert any("libavcodec" in o for o in objects)

# Ctrl-C during a long call: SIGINT sent to this process from a timer raises
# KeyboardInterrupt within a second, the module keeps working afterwards, and an interrupted
# render leaves nothing under the requested name.
import os
import signal
import threading
import time

import pytest

import chainbreak


def long_scene():
    # ~ a minute of RK4 on this machine: far longer than the test waits.
    return chainbreak.Scene.from_dict({
        "chain": {"beads": 20000},
        "drive": {"type": "ramp", "beta": 0.001},
        "integrator": {"dt": 0.01, "t_end": 100000.0},
    })


def interrupt_after(seconds):
    sent = {}

    def fire():
        sent["at"] = time.monotonic()
        os.kill(os.getpid(), signal.SIGINT)

    timer = threading.Timer(seconds, fire)
    timer.start()
    return timer, sent


@pytest.mark.parametrize("call", ["run", "sweep", "render"])
def test_sigint_raises_keyboard_interrupt_within_a_second(tmp_path, call):
    assert signal.getsignal(signal.SIGINT) is signal.default_int_handler
    scene = long_scene()
    video = tmp_path / "long.mp4"
    timer, sent = interrupt_after(0.5)
    start = time.monotonic()
    with pytest.raises(KeyboardInterrupt):
        if call == "run":
            chainbreak.run(scene, every=1000)
        elif call == "sweep":
            chainbreak.sweep(scene, vary={"drive.beta": [0.001, 0.002]}, jobs=1)
        else:
            # Few beads: the physics pre-pass (not interruptible, measure_run) is quick and
            # the ~3000 frames are the long part.
            scene.set("chain.beads", 30)
            scene.set("integrator.t_end", 2000.0)
            chainbreak.render(scene, str(video), quality="l", overlay=False)
    raised = time.monotonic()
    timer.join()
    assert "at" in sent, "the call ended before the signal: make the scene longer"
    assert raised - sent["at"] < 1.0
    assert raised - start < 5.0
    assert not video.exists()  # nothing half-written under the requested name
    # The stop flag is cleared: the next call runs to the end.
    small = chainbreak.Scene.from_toml(
        '[chain]\nbeads = 5\n[drive]\ntype = "step"\namplitude = 1\n[integrator]\nt_end = 1.0\n')
    assert chainbreak.run(small).tau[-1] == 1.0

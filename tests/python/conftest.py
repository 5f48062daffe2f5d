# pytest fixtures for the Python module's tests. ctest runs them (tests/CMakeLists.txt) with
# PYTHONPATH=build/python and CHAINBREAK_EXE / CHAINBREAK_SCENES / CHAINBREAK_TEST_DATA set;
# by hand: PYTHONPATH=build/python CHAINBREAK_EXE=build/chainbreak python3 -m pytest tests/python
import os
import pathlib
import subprocess

import pytest

ROOT = pathlib.Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def exe():
    return os.environ.get("CHAINBREAK_EXE", str(ROOT / "build" / "chainbreak"))


@pytest.fixture(scope="session")
def scenes():
    return pathlib.Path(os.environ.get("CHAINBREAK_SCENES", ROOT / "scenes"))


@pytest.fixture(scope="session")
def data():
    return pathlib.Path(os.environ.get("CHAINBREAK_TEST_DATA", ROOT / "tests" / "data"))


@pytest.fixture(scope="session")
def cli(exe):
    """Runs the chainbreak CLI; fails the test on a non-zero status."""

    def run(*args):
        done = subprocess.run([exe, *map(str, args)], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        return done.stdout

    return run

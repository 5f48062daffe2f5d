# The README's notebook-style example (its "Python" section, the first ```python block) runs
# as a script, from the repository's top folder as the README says.
import pathlib
import re

import matplotlib

matplotlib.use("Agg")

ROOT = pathlib.Path(__file__).resolve().parents[2]


def test_readme_example_runs(tmp_path, monkeypatch):
    readme = (ROOT / "README.md").read_text()
    section = readme.split("\n## Python\n", 1)[1].split("\n## ", 1)[0]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    monkeypatch.chdir(ROOT)
    namespace = {"__name__": "__readme__"}
    exec(compile(code, "README.md (Python)", "exec"), namespace)
    # The example's names and what it computed.
    result, grid = namespace["result"], namespace["grid"]
    assert result.phi.shape[1] == namespace["scene"].beads
    assert len(grid["spring"]) == len(grid["drive.beta"])

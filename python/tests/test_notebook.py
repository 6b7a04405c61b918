"""examples/python/getting_started.ipynb executes (jupyter nbconvert --execute, Debian's jupyter-nbconvert and
python3-ipykernel), so that it never rots: every cell runs without error, its checks included."""

import json
import os
import shutil
import subprocess
import sys

import pytest

import mpm
from conftest import SOURCE_DIR


def jupyter():
    """Debian's jupyter (its python3 is the one with ipykernel), or this interpreter's module."""
    found = shutil.which("jupyter", path="/usr/bin") or shutil.which("jupyter")
    return [found] if found else [sys.executable, "-m", "jupyter"]


def test_the_getting_started_notebook_executes(tmp_path):
    notebook = SOURCE_DIR / "examples/python/getting_started.ipynb"
    # the kernel imports the package this test imports (PYTHONPATH made absolute: the kernel runs elsewhere)
    package_dir = os.path.dirname(os.path.dirname(os.path.abspath(mpm.__file__)))
    env = dict(os.environ, JUPYTER_PLATFORM_DIRS="1", PYDEVD_DISABLE_FILE_VALIDATION="1",
               PYTHONPATH=os.pathsep.join([package_dir, os.environ.get("PYTHONPATH", "")]))
    env.pop("MPLBACKEND", None)  # the kernel's inline backend draws the figure into the notebook
    r = subprocess.run([*jupyter(), "nbconvert", "--to", "notebook", "--execute", "--output-dir", str(tmp_path),
                        "--ExecutePreprocessor.timeout=120", str(notebook)],
                       capture_output=True, text=True, env=env, cwd=tmp_path)
    if "No module named 'nbconvert'" in r.stderr or "No module named 'ipykernel" in r.stderr:
        pytest.fail("jupyter nbconvert or the kernel is not installed (Debian: jupyter-nbconvert python3-ipykernel)")
    assert r.returncode == 0, r.stderr[-3000:]
    executed = json.loads((tmp_path / "getting_started.ipynb").read_text())
    outputs = [o for c in executed["cells"] if c["cell_type"] == "code" for o in c.get("outputs", [])]
    assert not [o for o in outputs if o["output_type"] == "error"]
    text = "".join("".join(o.get("text", "")) for o in outputs)
    assert "SceneError: solver.cfl: out of range" in text
    assert "total energy:" in text
    html = "".join("".join(o.get("data", {}).get("text/html", "")) for o in outputs)
    assert "<progress" in html  # the progress bar, drawn as HTML in Jupyter
    assert any("image/png" in o.get("data", {}) for o in outputs)  # the figure

"""The README's Python examples cannot go stale: every ``python`` block runs as written, from
the repository's root (its relative paths), and the numbers its comments state hold."""

import os
import re
import warnings

import numpy as np
import pytest

import ballscrew

from conftest import ROOT

README = (ROOT / "README.md").read_text(encoding="utf-8")
BLOCKS = re.findall(r"^```python\n(.*?)^```", README, flags=re.S | re.M)


def test_the_readme_has_its_python_examples():
    assert len(BLOCKS) >= 3
    assert any("ballscrew.diagnose(" in b for b in BLOCKS)


@pytest.mark.parametrize("index", range(len(BLOCKS)))
def test_every_python_example_runs(index, monkeypatch):
    monkeypatch.chdir(ROOT)
    namespace = {}
    with warnings.catch_warnings():
        # The errors="nan" example warns by design; any other warning is a failure.
        warnings.simplefilter("error")
        warnings.simplefilter("ignore", ballscrew.EvaluationWarning)
        exec(compile(BLOCKS[index], f"README.md python block {index + 1}", "exec"), namespace)


def test_the_numbers_the_examples_state():
    screw = ballscrew.Screw.dkfzd4012()
    # "screw.torque(2000.0)  # 0.1811 N m at 2000 N preload, 100 rpm (oil at 40 C)"
    assert round(float(screw.torque(2000.0)), 4) == 0.1811
    assert "0.1811 N m at 2000 N preload" in README
    # "(6, 2) array"
    assert screw.torque(np.linspace(500, 3000, 6)[:, None], speed_rpm=[100.0, -100.0]).shape == (6, 2)
    # "[0.181, nan] + EvaluationWarning"
    with pytest.warns(ballscrew.EvaluationWarning):
        t = screw.torque(2000.0, axial_load_n=[0.0, 1e6], errors="nan")
    assert round(float(t[0]), 3) == 0.181 and np.isnan(t[1])
    assert "[0.181, nan] + EvaluationWarning" in README


def test_the_examples_refer_to_files_of_the_repository():
    for block in BLOCKS:
        for path in re.findall(r'"((?:configs|tests)/[^"]+)"', block):
            assert os.path.exists(ROOT / path), path

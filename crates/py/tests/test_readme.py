"""The README's and the guide's Python examples cannot go stale: every ``python`` block of the
README and of the guide's pages (``docs/*.md``; the blocks of ``docs/fleet.md`` and
``docs/fmu.md`` need a fleet of files and an FMU, and run in ``test_docs_examples.py``) runs as
written, from the repository's root (its relative paths). The blocks of one page run in order in
one namespace, as a reader types them one after the other (a block inside a list item too). The
numbers the comments state hold."""

import os
import re
import textwrap
import warnings

import numpy as np
import pytest

import ballscrew

from conftest import ROOT

OWN_HARNESS = {"fleet.md", "fmu.md"}
PAGES = [ROOT / "README.md"] + sorted(p for p in (ROOT / "docs").glob("*.md") if p.name not in OWN_HARNESS)
README = (ROOT / "README.md").read_text(encoding="utf-8")


def blocks(path):
    """The python blocks of a page, dedented as far as their fence."""
    text = path.read_text(encoding="utf-8")
    found = re.findall(r"^( *)```python\n(.*?)^\1```", text, flags=re.S | re.M)
    return [textwrap.dedent("".join(line[len(indent):] for line in body.splitlines(keepends=True)))
            for indent, body in found]


PAGES_WITH_BLOCKS = [p for p in PAGES if blocks(p)]


def test_the_pages_have_their_python_examples():
    names = [p.name for p in PAGES_WITH_BLOCKS]
    assert "README.md" in names and "python.md" in names and "diagnosis.md" in names, names
    assert any("ballscrew.diagnose(" in b for p in PAGES for b in blocks(p))
    # The blocks inside list items (the Evaluator's and the Reversal's) are found too.
    assert len(blocks(ROOT / "docs" / "python.md")) >= 3


@pytest.mark.parametrize("page", PAGES_WITH_BLOCKS, ids=lambda p: p.name)
def test_every_python_example_runs(page, monkeypatch):
    monkeypatch.chdir(ROOT)
    namespace = {"__name__": "docs_example"}
    for k, block in enumerate(blocks(page)):
        with warnings.catch_warnings():
            # The errors="nan" example warns by design; any other warning is a failure.
            warnings.simplefilter("error")
            warnings.simplefilter("ignore", ballscrew.EvaluationWarning)
            exec(compile(block, f"{page.relative_to(ROOT)} python block {k + 1}", "exec"), namespace)


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
    for page in PAGES:
        for block in blocks(page):
            for path in re.findall(r'"((?:configs|tests)/[^"]+)"', block):
                assert os.path.exists(ROOT / path), (page.name, path)

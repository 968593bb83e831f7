"""The Python examples of docs/ cannot go stale: every ``python`` block of docs/fleet.md and
docs/fmu.md runs as written, in a directory that holds what the page says it holds (``configs/``,
a ``fleet/`` of CSV files, the FMU ``dkfzd4012.fmu`` its ``sh`` block builds). Blocks guarded by
``if __name__ == "__main__":`` (a pool of worker processes: what the engines themselves do, run
in crates/py/tests/test_fleet.py) run with their functions defined and the guarded part left
out; each function such a block defines is then called on one machine."""

import os
import re
import shutil
import warnings

import pytest

import ballscrew

from conftest import ROOT
from test_fleet import write_fleet


def blocks(page):
    text = (ROOT / "docs" / page).read_text(encoding="utf-8")
    return re.findall(r"^```python\n(.*?)^```", text, flags=re.S | re.M)


def run(block, namespace, name):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        exec(compile(block, name, "exec"), namespace)


def test_the_pages_have_their_examples():
    assert len(blocks("fleet.md")) >= 4
    assert len(blocks("fmu.md")) >= 1


def test_fleet_examples_run(tmp_path, monkeypatch):
    os.symlink(ROOT / "configs", tmp_path / "configs")
    (tmp_path / "fleet").mkdir()
    write_fleet(tmp_path / "fleet", ballscrew.Screw.dkfzd4012())
    monkeypatch.chdir(tmp_path)
    namespace = {"__name__": "docs_fleet_example"}
    ran = 0
    for k, block in enumerate(blocks("fleet.md")):
        if "import dask" in block:
            pytest.importorskip("dask")
        run(block, namespace, f"docs/fleet.md python block {k + 1}")
        ran += 1
        if "reports" in namespace and "if __name__" not in block:
            # Each report names the calibration it found (the machines wear: a finding each).
            assert len(namespace["reports"]) == len(namespace["paths"]) > 0
            assert all("calibration" in r for r in namespace["reports"])
    # The guarded block's function, on one machine.
    path, findings = namespace["wear_rate"](namespace["paths"][0], namespace["screw"])
    assert path == namespace["paths"][0] and isinstance(findings, list)
    assert ran == len(blocks("fleet.md"))


def test_fmu_example_runs(cli, tmp_path, monkeypatch):
    pytest.importorskip("fmpy")
    page = (ROOT / "docs" / "fmu.md").read_text(encoding="utf-8")
    assert "ballscrew fmu --out dkfzd4012.fmu" in page
    cli("fmu", "--out", str(tmp_path / "dkfzd4012.fmu"))
    monkeypatch.chdir(tmp_path)
    for k, block in enumerate(blocks("fmu.md")):
        namespace = {"__name__": "docs_fmu_example"}
        run(block, namespace, f"docs/fmu.md python block {k + 1}")
        if "result" in namespace:
            torque = namespace["result"]["torque_nm"]
            assert len(torque) > 100 and all(abs(t) < 10.0 for t in torque)

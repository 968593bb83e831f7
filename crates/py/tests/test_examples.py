"""The Python examples (crates/py/examples) run as written, from the repository's root, and
what they print is what the library computes: each is run with ``runpy`` and a number it states
is checked against a call of its own here."""

import re
import runpy

import numpy as np
import pytest

import ballscrew

from conftest import ROOT

EXAMPLES = ROOT / "crates" / "py" / "examples"


def run(name, monkeypatch, capsys):
    """Runs the example ``name`` from the repository's root; its globals and its output."""
    monkeypatch.chdir(ROOT)
    namespace = runpy.run_path(str(EXAMPLES / name), run_name="__main__")
    return namespace, capsys.readouterr().out


def printed(out, label):
    """The first number after ``label:`` on the line that starts with it."""
    line = next((l for l in out.splitlines() if l.startswith(label + ":")), None)
    assert line is not None, f"no line `{label}:` in\n{out}"
    return float(re.search(r"[-+]?\d+(\.\d+)?(e[-+]?\d+)?", line[len(label) + 1 :]).group())


def test_every_example_is_tested():
    assert sorted(p.name for p in EXAMPLES.glob("*.py")) == ["drive_cycle.py", "predict_dataframe.py", "xjtu_diagnosis.py"]


def test_drive_cycle(monkeypatch, capsys):
    ns, out = run("drive_cycle.py", monkeypatch, capsys)
    screw = ballscrew.Screw.dkfzd4012()
    # The peak is the running torque at 1500 rpm (the f64 evaluator is within 1e-8 of the model).
    assert printed(out, "peak torque") == pytest.approx(screw.torque(2000.0, speed_rpm=1500.0), abs=5e-5)
    # The RMS and the friction's energy from the model's torques point by point.
    speed_rpm = ns["profile_rpm"]()
    torque = screw.torque(np.full(speed_rpm.shape, 2000.0), speed_rpm=speed_rpm)
    assert printed(out, "rms torque") == pytest.approx(np.sqrt(np.mean(torque**2)), abs=5e-5)
    energy = np.sum(torque * speed_rpm * 2 * np.pi / 60) * 1e-3
    assert printed(out, "friction energy over the cycle") == pytest.approx(energy, abs=5e-3)
    assert energy > 0.0


def test_predict_dataframe(monkeypatch, capsys):
    ns, out = run("predict_dataframe.py", monkeypatch, capsys)
    frame = ns["frame"]
    screw = ballscrew.Screw.dkfzd4012()
    for point, row in frame.iterrows():
        want = screw.torque(row["preload_n"], speed_rpm=row["speed_rpm"], axial_load_n=row["axial_load_n"])
        assert row["torque_nm"] == pytest.approx(want, rel=1e-9), point
        line = next(l for l in out.splitlines() if l.startswith(point))
        assert float(line.split()[-1]) == pytest.approx(want, abs=5e-5), line
    # The axial load's torque F_a L / (2 pi) is in the drive torque: running back, the drag
    # is negative and the 500 N load's torque positive.
    s = screw.summary(2000.0, speed_rpm=-300.0, axial_load_n=500.0)
    assert s["drag_torque_nm"] < 0.0 and s["load_torque_nm"] == pytest.approx(500.0 * screw.lead_m / (2 * np.pi))
    assert frame.loc["loaded back", "torque_nm"] == pytest.approx(s["drag_torque_nm"] + s["load_torque_nm"], rel=1e-9)


def test_xjtu_diagnosis(monkeypatch, capsys):
    ns, out = run("xjtu_diagnosis.py", monkeypatch, capsys)
    assert printed(out, "rows") == len(ns["report"]["row_torques"]["measured_torque_nm"]) > 10
    assert "findings: preload_loss" in out
    r = ballscrew.diagnose(
        str(ROOT / "tests/data/xjtu-ball-screw/friction_torque.csv"),
        spec=str(ROOT / "configs/xjtu-32x8.toml"),
        columns={"time_h": "hours", "torque_nm": "upper_screw_torque_Nm"},
    )
    loss = r["findings"][0]["parameters"]["loss_per_1000_h"]
    assert printed(out, "preload loss") == pytest.approx(100 * loss, abs=5e-3) and loss > 0.0
    assert printed(out, "held-out RMSE cut by the finding") == pytest.approx(100 * r["gain"]["heldout_rmse_cut"], abs=0.05)
    assert r["gain"]["heldout_rmse_cut"] >= 0.3

"""The FMI 2.0 co-simulation FMU that `ballscrew fmu` packages, run by FMPy: FMPy's validation,
a simulation through reversals and standstill against `Evaluator.series` on the same points, and
a bad spec inside the FMU (an error with the core's message in the log, not a crash).

FMPy is installed by tests/all.sh; without it the module is skipped. The command line comes from
BALLSCREW_CLI (as for the parity tests), its FMU library from beside it (`cargo build --release -p
ballscrew-fmu`)."""

import math
import subprocess
import zipfile
from pathlib import Path

import numpy as np
import pytest

import ballscrew

fmpy = pytest.importorskip("fmpy")
from fmpy.validation import validate_fmu  # noqa: E402

# The FMU and `Evaluator.series` run the same evaluator over the same points in the same order.
RTOL = 1e-9
OUTPUTS = ["speed_rad_s", "axial_load_n", "torque_nm", "drag_torque_nm", "load_torque_nm", "dissipated_power_w"]


def rpm_to_rad_s(rpm):
    # The core's conversion, operation for operation (`ballscrew_core::input::rpm_to_rad_s`).
    return rpm * 2.0 * math.pi / 60.0


@pytest.fixture(scope="module")
def fmus(cli, repo_root, tmp_path_factory):
    """The FMU of the built-in spec and of configs/dkfzd4012-dry.toml (by --spec)."""
    out = tmp_path_factory.mktemp("fmu")
    builtin = out / "dkfzd4012.fmu"
    dry_spec = repo_root / "configs" / "dkfzd4012-dry.toml"
    dry = out / "dry.fmu"
    try:
        cli("fmu", "--out", str(builtin))
        cli("fmu", "--spec", str(dry_spec), "--out", str(dry))
    except subprocess.CalledProcessError as e:
        pytest.fail(f"ballscrew fmu failed: {e.stderr}")
    return {
        "builtin": (builtin, ballscrew.Screw.dkfzd4012()),
        "dry": (dry, ballscrew.Screw.from_toml(dry_spec)),
    }


def test_the_archive_holds_description_library_and_spec(fmus, repo_root):
    path, _ = fmus["dry"]
    with zipfile.ZipFile(path) as z:
        assert sorted(z.namelist()) == ["binaries/linux64/ballscrew.so", "modelDescription.xml", "resources/spec.toml"]
        assert z.read("resources/spec.toml") == (repo_root / "configs" / "dkfzd4012-dry.toml").read_bytes()
    md = fmpy.read_model_description(str(path))
    assert md.fmiVersion == "2.0" and md.coSimulation.modelIdentifier == "ballscrew"
    assert md.modelName == "dkfzd4012-dry"
    units = {v.name: (v.causality, v.variability, v.unit) for v in md.modelVariables}
    assert units == {
        "speed_rad_s": ("input", "continuous", "rad/s"),
        "axial_load_n": ("input", "continuous", "N"),
        "preload_n": ("parameter", "tunable", "N"),
        "torque_nm": ("output", "continuous", "N.m"),
        "drag_torque_nm": ("output", "continuous", "N.m"),
        "load_torque_nm": ("output", "continuous", "N.m"),
        "dissipated_power_w": ("output", "continuous", "W"),
    }


@pytest.mark.parametrize("which", ["builtin", "dry"])
def test_fmpy_validation_finds_no_problem(fmus, which):
    problems = validate_fmu(str(fmus[which][0]))
    assert problems == []


def profile():
    """Speed (rad/s) and axial load (N) against time (s): up, through a reversal, a standstill,
    a slow creep through zero, and up again under a changing load."""
    t = np.round(np.arange(0.0, 0.4001, 0.001), 12)
    rpm = np.interp(t, [0.0, 0.05, 0.1, 0.15, 0.2, 0.25, 0.3, 0.32, 0.36, 0.4], [0, 600, 600, -400, -400, 0, 0, -5, 5, 300])
    load = 400.0 * np.sin(2 * np.pi * t / 0.4)
    signal = np.zeros(len(t), dtype=[("time", np.float64), ("speed_rad_s", np.float64), ("axial_load_n", np.float64)])
    signal["time"], signal["speed_rad_s"], signal["axial_load_n"] = t, rpm_to_rad_s(rpm), load
    return signal


@pytest.mark.parametrize("which", ["builtin", "dry"])
def test_simulation_equals_evaluator_series(fmus, which):
    path, screw = fmus[which]
    preload = 1500.0
    signal = profile()
    result = fmpy.simulate_fmu(
        str(path),
        start_time=0.0,
        stop_time=0.4,
        step_size=0.001,
        output_interval=0.001,
        start_values={"preload_n": preload},
        input=signal,
        output=OUTPUTS,
        validate=True,
    )
    speed, load = result["speed_rad_s"], result["axial_load_n"]
    assert len(result) == len(signal)
    # The profile turns both ways and stands still.
    assert speed.max() > 60 and speed.min() < -40 and np.count_nonzero(speed == 0.0) >= 10
    assert np.any((speed > 0) & (speed < 1)) and np.any((speed < 0) & (speed > -1))
    # The same points, in the same order, warm-started the same way.
    want = ballscrew.Evaluator(screw).series(preload, speed_rpm=speed * 60.0 / (2.0 * math.pi), axial_load_n=load)
    got = result["torque_nm"]
    np.testing.assert_allclose(got, want, rtol=RTOL, atol=0.0)
    nonzero = want != 0.0
    worst = np.max(np.abs(got[nonzero] - want[nonzero]) / np.abs(want[nonzero]))
    print(f"{which}: {len(got)} points, largest relative difference FMU vs Evaluator.series {worst:.3e}")
    # The parts: the load torque as the model reports it, the drag the rest, the power drag * speed.
    lead_torque_per_n = screw.summary(preload, 100.0, 1000.0)["load_torque_nm"] / 1000.0
    np.testing.assert_allclose(result["load_torque_nm"], load * lead_torque_per_n, rtol=1e-12, atol=1e-15)
    np.testing.assert_allclose(result["drag_torque_nm"], got - result["load_torque_nm"], rtol=0, atol=1e-15)
    np.testing.assert_array_equal(result["dissipated_power_w"], result["drag_torque_nm"] * speed)
    # Friction dissipates: the drag opposes the motion.
    assert np.all(result["dissipated_power_w"] >= 0.0)
    assert np.all(result["dissipated_power_w"][np.abs(speed) > 1.0] > 0.0)


def test_bad_spec_inside_the_fmu_is_an_error_in_the_log(fmus, tmp_path):
    source, _ = fmus["builtin"]
    bad = tmp_path / "bad.fmu"
    with zipfile.ZipFile(source) as zin, zipfile.ZipFile(bad, "w", zipfile.ZIP_DEFLATED) as zout:
        for item in zin.infolist():
            data = zin.read(item)
            if item.filename == "resources/spec.toml":
                text = data.decode()
                assert "pitch_diameter_mm = 40.0" in text
                data = text.replace("pitch_diameter_mm = 40.0", "pitch_diameter_mm = -40.0").encode()
            zout.writestr(item, data)
    messages = []

    def logger(component, instance_name, status, category, message):
        messages.append((status, message.decode()))

    with pytest.raises(Exception, match="(?i)instantiate"):
        fmpy.simulate_fmu(str(bad), stop_time=0.01, step_size=0.001, logger=logger)
    errors = [m for s, m in messages if s == 3]  # fmi2Error
    assert len(errors) == 1, messages
    assert "resources/spec.toml" in errors[0] and "invalid geometry.pitch_diameter_mm: -40 mm" in errors[0], errors
    # The spec differs from the one the GUID was made for: a warning would say so, but the
    # spec is refused first.
    assert all(s != 4 for s, _ in messages)  # no fmi2Fatal


def test_invalid_input_is_an_error_not_a_number(fmus, tmp_path):
    path, _ = fmus["builtin"]
    messages = []

    def logger(component, instance_name, status, category, message):
        messages.append((status, message.decode()))

    signal = profile()[:20].copy()
    signal["speed_rad_s"][10:] = np.nan
    with pytest.raises(Exception):
        fmpy.simulate_fmu(str(path), stop_time=0.019, step_size=0.001, input=signal, logger=logger)
    assert any(s == 3 and "invalid speed_rad_s: NaN" in m for s, m in messages), messages

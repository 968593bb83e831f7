"""Every error path raises ValueError with the core's message; nothing crashes the interpreter."""

import math
import os
import subprocess
import sys

import numpy as np
import pytest

import ballscrew


@pytest.fixture(scope="module")
def screw():
    return ballscrew.Screw.dkfzd4012()


@pytest.fixture(scope="module")
def toml(repo_root):
    return (repo_root / "configs" / "dkfzd4012.toml").read_text()


def test_invalid_toml_names_the_origin_line_and_column():
    with pytest.raises(ValueError, match=r"^mine\.toml:1:\d+: "):
        ballscrew.Screw.from_toml_str("[geometry\npitch_diameter_mm = 40", origin="mine.toml")


def test_unknown_key_is_named(toml):
    with pytest.raises(ValueError, match="tip_radius_mm"):
        ballscrew.Screw.from_toml_str(toml.replace("[material]", "tip_radius_mm = 3.0\n\n[material]"))


def test_missing_key_is_named(toml):
    with pytest.raises(ValueError, match="lead_mm"):
        ballscrew.Screw.from_toml_str(toml.replace("lead_mm = 12.0", ""))


@pytest.mark.parametrize(
    "old, new, message",
    [
        ("conformity_screw = 0.52", "conformity_screw = 0.45",
         r"invalid geometry\.conformity_screw: 0\.45 \(valid: \[0\.501, 0\.6\]\)"),
        ("coefficient = 0.03", "coefficient = 0.001", r"invalid friction\.coefficient: 0\.001 \(valid: \[0\.005, 1\]\)"),
        ("nuts = 2", "nuts = 3", r"invalid geometry\.nuts: 3 \(valid: 1 or 2\)"),
        ("preload_n = 2000.0", "preload_n = -5.0", r"invalid operating\.preload_n: -5 N \(valid: finite, \[0 N, 10 MN\]\)"),
        ("poisson_ratio = 0.3", "poisson_ratio = nan", r"invalid material\.poisson_ratio: NaN"),
        ('torque = "energy"', 'torque = "guess"', r"guess"),
    ],
)
def test_out_of_range_fields_name_the_key_the_value_and_the_range(toml, old, new, message):
    assert old in toml
    with pytest.raises(ValueError, match=message):
        ballscrew.Screw.from_toml_str(toml.replace(old, new), origin="spec.toml")


def test_missing_file_is_a_file_not_found_error_naming_it(tmp_path):
    with pytest.raises(FileNotFoundError, match="nowhere.toml") as e:
        ballscrew.Screw.from_toml(tmp_path / "nowhere.toml")
    assert e.value.filename == str(tmp_path / "nowhere.toml")


@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf, -1.0, 2e7])
def test_bad_preload_scalar(screw, bad):
    with pytest.raises(ValueError, match=r"^invalid preload_n: .* \(valid: finite, \[0 N, 10 MN\]\)"):
        screw.torque(bad)


@pytest.mark.parametrize("bad", [math.nan, math.inf, 1e9])
def test_bad_speed_is_named_in_rpm(screw, bad):
    with pytest.raises(ValueError, match=r"^invalid speed_rpm: .* \(valid: finite, \|speed\| <= 30000 rpm\)"):
        screw.torque(1000.0, speed_rpm=bad)


@pytest.mark.parametrize("arg", ["preload_n", "speed_rpm", "axial_load_n"])
@pytest.mark.parametrize("bad", [math.nan, math.inf, -math.inf])
def test_nan_and_inf_in_arrays_are_rejected_with_the_index(screw, arg, bad):
    values = {"preload_n": [500.0, 1000.0, 1500.0], "speed_rpm": [100.0, 100.0, 100.0], "axial_load_n": [0.0, 0.0, 0.0]}
    values[arg] = list(values[arg])
    values[arg][2] = bad
    arrays = {k: np.array(v) for k, v in values.items()}
    with pytest.raises(ValueError, match=rf"^invalid {arg}: .* at index \(2,\) of the operating points"):
        screw.torque(**arrays)


def test_negative_preload_in_a_2d_batch_names_its_index(screw):
    p = np.full((2, 3), 1000.0)
    p[1, 0] = -3.0
    with pytest.raises(ValueError, match=r"invalid preload_n: -3 N .*at index \(1, 0\)"):
        screw.torque(p)


@pytest.mark.parametrize(
    "preload, speed",
    [(np.ones(3) * 1000, np.ones(4) * 100), (np.ones((2, 3)) * 1000, np.ones((3, 2)) * 100)],
)
def test_shapes_that_do_not_broadcast(screw, preload, speed):
    with pytest.raises(ValueError, match=r"shapes do not broadcast together: preload_n \(.*\), speed_rpm \("):
        screw.torque(preload, speed_rpm=speed)


@pytest.mark.parametrize("bad", ["fast", [1.0, "x"], {"a": 1}, None, object()])
def test_non_numbers_are_value_errors(screw, bad):
    with pytest.raises(ValueError, match="preload_n"):
        screw.torque(bad)


def test_huge_integers_are_value_errors(screw):
    with pytest.raises(ValueError, match="preload_n"):
        screw.torque(10**400)


def test_no_quasi_static_state_is_a_convergence_error(screw, toml):
    # docs/prediction.md: from about 15 N of ball-ball load on, the lightest circle's balls skid (dry model).
    if 'lubrication = "ehl"' in toml:
        dry = toml.replace('lubrication = "ehl"', 'lubrication = "dry"')
    else:
        dry = toml.replace("[model]\n", '[model]\nlubrication = "dry"\n')
    # The load between balls set (the paper's parameter), not the ball train's.
    skid = ballscrew.Screw.from_toml_str(dry.replace("[friction]\n", "[friction]\nball_ball_load_n = 20.0\n", 1))
    with pytest.raises(ballscrew.ConvergenceError, match=r"ball balance did not converge .* preload_n 2000"):
        skid.torque(2000.0)
    # Both points fail, one on each thread: the first in order is reported.
    with pytest.raises(ValueError, match=r"did not converge .*index \(0,\)"):
        skid.torque(np.array([2000.0, 2000.0]))
    assert issubclass(ballscrew.ConvergenceError, ValueError)


def test_sweep_and_inspect_reject_bad_input(screw):
    with pytest.raises(ValueError, match="preload_n"):
        screw.sweep(np.ones((2, 2)) * 1000.0)
    with pytest.raises(ValueError, match="preload_n"):
        screw.sweep([])
    with pytest.raises(ValueError, match="invalid preload_n: NaN"):
        screw.sweep([1000.0, math.nan])
    with pytest.raises(ValueError, match="one operating point"):
        screw.inspect(np.array([1000.0, 2000.0]))
    with pytest.raises(ValueError, match="invalid axial_load_n"):
        screw.inspect(1000.0, axial_load_n=math.inf)
    with pytest.raises(ValueError, match="invalid speed_rpm"):
        screw.summary(1000.0, speed_rpm=-1e6)


def test_the_screw_still_works_after_errors(screw):
    for bad in (math.nan, -1.0, "x"):
        with pytest.raises(ValueError):
            screw.torque(bad)
    assert screw.torque(2000.0) == pytest.approx(ballscrew.dkfzd4012_torque_nm(2000.0), rel=1e-12)


ODD = [0.0, -0.0, 1e-300, -1e-300, 5e-324, 1e7, -1e7, 1e300, -1e300, math.nan, math.inf, -math.inf]


def test_odd_values_anywhere_give_a_result_or_a_value_error(screw):
    """No combination of odd floats escapes as anything but a number or ValueError."""
    outcomes = set()
    for p in (0.0, 1e-300, 5.0, 2000.0, 1e7, math.nan):
        for s in (0.0, -0.0, 0.05, -0.05, 30000.0, -30000.0, 1e-300, math.inf):
            for a in (0.0, -1e7, 1e7, 3000.0, math.nan):
                try:
                    t = screw.torque(p, speed_rpm=s, axial_load_n=a)
                    assert math.isfinite(t), (p, s, a, t)
                    outcomes.add("number")
                except ValueError:
                    outcomes.add("ValueError")
    assert outcomes == {"number", "ValueError"}


def test_standstill_gives_the_axial_term_alone(screw):
    # At 0 rpm the creep forces vanish (docs/model-notes.md item 13): T = F_a L / (2 pi) only.
    row = screw.summary(2000.0, speed_rpm=0.0, axial_load_n=100.0)
    assert row["dissipation_torque_nm"] == 0.0
    assert row["torque_nm"] == pytest.approx(row["load_torque_nm"], rel=1e-12)


@pytest.mark.parametrize("value", ODD)
@pytest.mark.parametrize("arg", ["semi_axis_rolling_mm", "semi_axis_lateral_mm", "normal_load_n", "xi", "eta",
                                 "phi_per_mm", "heathcote_per_mm2", "friction", "youngs_modulus_gpa",
                                 "poisson_ratio"])
def test_contact_with_odd_values_gives_a_result_or_a_value_error(arg, value):
    base = dict(semi_axis_rolling_mm=8.0, semi_axis_lateral_mm=4.0, normal_load_n=82e3, eta=-6e-4, grid=8)
    base[arg] = value
    positional = [base.pop(k) for k in ("semi_axis_rolling_mm", "semi_axis_lateral_mm", "normal_load_n")]
    try:
        r = ballscrew.contact(*positional, **base)
    except ValueError:
        return
    assert all(math.isfinite(r[k]) for k in ("force_e_n", "force_f_n", "spin_moment_nm", "dissipation_per_speed_n"))
    assert all(np.all(np.isfinite(r[k])) for k in ("traction_x_mpa", "traction_y_mpa", "bound_mpa", "slip_x", "slip_y"))


def test_none_as_preload_is_named_as_none_not_nan(screw):
    with pytest.raises(ValueError, match=r"invalid preload_n: None \(valid: a real number or an array"):
        screw.torque(None)


@pytest.mark.parametrize("text", ["2000", b"2000"])
def test_a_number_as_text_is_refused_not_parsed(screw, text):
    # numpy would parse "2000" as 2000.0: a text is not a number here.
    with pytest.raises(ValueError, match=r"invalid speed_rpm: b?'2000' \(valid: a real number"):
        screw.torque(2000.0, speed_rpm=text)


def test_a_broadcast_too_large_is_refused_before_anything_is_allocated(screw):
    # (1e5, 1) against (1, 1e4): 1e9 points, over the limit of 1e8; a vector of 1e9 points would
    # need 8 GB per column, and a failed allocation in Rust would abort the interpreter.
    preload = np.full((100_000, 1), 1000.0)
    speed = np.full((1, 10_000), 100.0)
    with pytest.raises(ValueError, match=r"broadcast shape \(100000, 10000\) \(valid: at most 100000000 points\)"):
        screw.torque(preload, speed_rpm=speed)
    # A broadcast shape whose size, 2**64, overflows a 64-bit count.
    p = np.broadcast_to(np.array(1000.0), (2**21, 1, 1))
    s = np.broadcast_to(np.array(100.0), (1, 2**21, 1))
    a = np.broadcast_to(np.array(0.0), (1, 1, 2**22))
    with pytest.raises(ValueError, match="at most 100000000 points"):
        screw.torque(p, speed_rpm=s, axial_load_n=a)


# Run in a child interpreter under a limit on its address space: 3e7 lubricated points, the
# limit 2 GB above what the child holds once its preloads are made. The three columns and the
# operating points of the call (48 bytes a point, 1.44 GB) fit; the batch's own vectors (its
# order, its points by band, its results) do not. The interpreter aborted (SIGABRT in the
# batch's threads); a MemoryError is what Python code can catch.
_OUT_OF_MEMORY = """
import resource, sys
import numpy as np
import ballscrew

screw = ballscrew.Screw.dkfzd4012()
preload = np.linspace(500.0, 3000.0, 30_000_000)
with open("/proc/self/status") as f:
    held = next(int(line.split()[1]) * 1024 for line in f if line.startswith("VmSize:"))
limit = held + 2 * 1024**3
try:
    resource.setrlimit(resource.RLIMIT_AS, (limit, limit))
except (ValueError, OSError) as e:
    print("SKIP", e)
    sys.exit(0)
try:
    screw.torque(preload, speed_rpm=100.0)
except MemoryError as e:
    print("MemoryError:", e)
    sys.exit(0)
print("no MemoryError")
sys.exit(3)
"""


def test_a_batch_that_runs_out_of_memory_raises_memory_error():
    resource = pytest.importorskip("resource")
    if not hasattr(resource, "RLIMIT_AS") or not os.path.exists("/proc/self/status"):
        pytest.skip("no limit on the address space here")
    r = subprocess.run([sys.executable, "-c", _OUT_OF_MEMORY], capture_output=True, text=True, timeout=900)
    if r.returncode == 0 and r.stdout.startswith("SKIP"):
        pytest.skip(f"setrlimit(RLIMIT_AS) refused: {r.stdout.strip()}")
    assert r.returncode == 0, f"exit {r.returncode} (a negative one is the signal that ended it)\n{r.stdout}\n{r.stderr}"
    assert r.stdout.startswith("MemoryError: "), r.stdout
    assert "out of memory" in r.stdout or "not enough memory" in r.stdout, r.stdout


@pytest.mark.parametrize("arg", ["speed_rpm", "axial_load_n"])
def test_sweep_speed_and_axial_load_are_numbers_or_one_array_of_them(screw, arg):
    with pytest.raises(ValueError, match=f"invalid {arg}: 'fast' \\(valid: a real number or an array of real numbers\\)"):
        screw.sweep(**{arg: "fast"})
    with pytest.raises(ValueError, match=rf"invalid {arg}: shape \(2, 1\) \(valid: a 1-d array of 1 to 100000"):
        screw.sweep(**{arg: [[100.0], [200.0]]})
    with pytest.raises(ValueError, match=f"one quantity at a time: preload_n and {arg} are both arrays"):
        screw.sweep([1000.0, 2000.0], **{arg: [100.0, 200.0]})
    with pytest.raises(ValueError, match="one quantity at a time: preload_n, speed_rpm and axial_load_n are all arrays"):
        screw.sweep([1000.0], speed_rpm=[100.0], axial_load_n=[0.0])
    with pytest.raises(ValueError, match=f"one quantity at a time: {arg} and oil_temperature_c are both arrays"):
        screw.sweep(oil_temperature_c=[20.0, 30.0], **{arg: [100.0, 200.0]})
    with pytest.raises(ValueError, match=rf"invalid {arg}: NaN .*index \(1,\)"):
        screw.sweep(**{arg: [100.0, math.nan]})


def test_a_sweep_has_at_most_the_command_lines_100000_preloads(screw):
    # Every row keeps its full summary; 1e8 rows (allowed for torque) would need about 20 GB.
    with pytest.raises(ValueError, match=r"invalid preload_n: shape \(100001,\) \(valid: a 1-d array of 1 to 100000"):
        screw.sweep(np.full(100_001, 1000.0))

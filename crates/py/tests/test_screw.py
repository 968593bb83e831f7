"""The Screw class: specs, read access, scalar and broadcast torque, sweep and inspect."""

import math
import sys
import threading
import types

import numpy as np
import pytest

import ballscrew


@pytest.fixture(scope="module")
def screw():
    return ballscrew.Screw.dkfzd4012()


def test_spec_fields_are_table_1_in_si_units(screw):
    # Table 1 of Xu et al. (2015) as in configs/dkfzd4012.toml (contact angle and ball split:
    # docs/model-notes.md item 14).
    assert screw.pitch_diameter_m == pytest.approx(40e-3, rel=1e-15)
    assert screw.lead_m == pytest.approx(12e-3, rel=1e-15)
    assert screw.ball_diameter_m == pytest.approx(5.953e-3, rel=1e-15)
    assert (screw.conformity_screw, screw.conformity_nut) == (0.52, 0.52)
    assert screw.contact_angle_deg == pytest.approx(45.0, rel=1e-14)
    assert (screw.nuts, screw.circles_per_nut, screw.balls_per_circle) == (2, 4, 19)
    assert screw.youngs_modulus_pa == pytest.approx(210e9, rel=1e-15)
    assert screw.poisson_ratio == 0.3
    assert screw.friction_coefficient == 0.03
    # No load between balls set: the ball train's (the spec's [circulation]).
    assert screw.ball_ball_load_n is None
    assert screw.standstill_speed_rpm == pytest.approx(0.1, rel=1e-12)
    assert screw.default_speed_rpm == pytest.approx(100.0, rel=1e-12)
    assert (screw.default_preload_n, screw.default_axial_load_n) == (2000.0, 0.0)
    # Helix angle atan(L / (pi d_m)) = atan(12 / (40 pi)).
    assert screw.helix_angle_deg == pytest.approx(math.degrees(math.atan(12.0 / (40.0 * math.pi))), rel=1e-12)
    assert (screw.load_distribution, screw.creep_coefficients, screw.torque_route) == (
        "geometric", "kalker-table", "energy")
    assert (screw.heathcote, screw.spin_moment, screw.contact_theory, screw.fastsim_grid) == (
        True, "combined", "linear-saturated", 20)
    assert "built-in DKFZD4012" in screw.origin and "2 nut(s) x 4 circles x 19 balls" in repr(screw)


def test_spec_fields_are_read_only(screw):
    with pytest.raises(AttributeError):
        screw.lead_m = 0.01


def test_toml_round_trip_and_files(screw, tmp_path, repo_root):
    again = ballscrew.Screw.from_toml_str(screw.to_toml())
    assert again.torque(1200.0) == pytest.approx(screw.torque(1200.0), rel=1e-12)
    from_file = ballscrew.Screw.from_toml(repo_root / "configs" / "dkfzd4012.toml")
    assert from_file.torque(2000.0) == pytest.approx(screw.torque(2000.0), rel=1e-12)
    text = screw.to_toml().replace("balls_per_circle = 19", "balls_per_circle = 10")
    fewer = ballscrew.Screw.from_toml_str(text, origin="ten balls")
    assert fewer.balls_per_circle == 10 and fewer.origin == "ten balls"
    # Same preload over fewer balls: each ball carries more, the torque stays of the same order.
    assert 0.5 < fewer.torque(2000.0) / screw.torque(2000.0) < 2.0


def test_scalars_give_a_float_that_rises_with_preload(screw):
    t = screw.torque(2000.0)
    assert type(t) is float
    assert 0.0 < screw.torque(500) < t < screw.torque(3000.0)
    assert type(screw.torque(np.float64(2000.0))) is float
    assert type(screw.torque(np.array(2000.0))) is float  # 0-d array
    # The lubricated table (README, docs/prediction.md): 0.1811 N m at 2000 N, 100 rpm.
    assert t == pytest.approx(0.1811, abs=5e-5)


def test_reverse_rotation_reverses_the_torque(screw):
    assert screw.torque(2000.0, speed_rpm=-100.0) == pytest.approx(-screw.torque(2000.0, speed_rpm=100.0), rel=1e-6)


def test_scalar_calls_agree_with_cold_evaluations(screw):
    for p in (3000.0, 700.0, 2000.0):
        assert screw.torque(p) == pytest.approx(ballscrew.dkfzd4012_torque_nm(p), rel=1e-12)


def test_legacy_dkfzd4012_function_is_the_built_in_screw(screw):
    assert ballscrew.dkfzd4012_torque_nm(1500.0, speed_rpm=200.0) == pytest.approx(
        screw.torque(1500.0, speed_rpm=200.0), rel=1e-12)


@pytest.mark.parametrize(
    "preload, speed, axial, shape",
    [
        ([500.0, 1000.0, 2000.0], None, None, (3,)),
        (np.array([[500.0], [1000.0]]), np.array([50.0, 100.0, -100.0]), None, (2, 3)),
        (1000.0, np.array([50.0, 100.0]), np.zeros((3, 1)), (3, 2)),
        (np.arange(500, 3001, 500, dtype=np.int64), 100, 0, (6,)),
        (np.empty((0,)), None, None, (0,)),
        (np.full((2, 1, 2), 1500.0), np.array([[100.0], [200.0], [300.0]]), 0.0, (2, 3, 2)),
    ],
)
def test_arrays_broadcast_to_numpys_shape(screw, preload, speed, axial, shape):
    kwargs = {k: v for k, v in (("speed_rpm", speed), ("axial_load_n", axial)) if v is not None}
    out = screw.torque(preload, **kwargs)
    assert isinstance(out, np.ndarray) and out.dtype == np.float64 and out.shape == shape
    p, s, a = np.broadcast_arrays(
        np.asarray(preload, dtype=float),
        np.asarray(speed if speed is not None else screw.default_speed_rpm, dtype=float),
        np.asarray(axial if axial is not None else 0.0, dtype=float),
    )
    for idx in np.ndindex(shape):
        expected = ballscrew.dkfzd4012_torque_nm(float(p[idx]), float(s[idx])) if a[idx] == 0.0 else None
        if expected is not None:
            assert out[idx] == pytest.approx(expected, rel=1e-12), idx


# A batch is every point's canonical state (docs/real-time.md, "One question, one answer"): the
# scalar call's bits.


def test_batch_of_1e5_points_on_the_evaluator_is_within_its_agreement(screw):
    # 200 preloads x 5 axial loads x 100 speeds (both directions), C order, on the dry model, with
    # start="warm": the control-loop evaluator band by band of speed (docs/real-time.md, "Batches
    # on the evaluator"), within its 1e-8 of the canonical torque (the scalar calls, at every
    # 97th point: a scalar loop over 1e5 points would take minutes).
    screw = ballscrew.Screw.from_toml_str(screw.to_toml().replace('lubrication = "ehl"', 'lubrication = "dry"'))
    preload = np.linspace(500.0, 3000.0, 200)[:, None, None]
    axial = np.array([-300.0, -100.0, 0.0, 150.0, 400.0])[None, :, None]
    speed = np.concatenate([np.linspace(-1500.0, -1.0, 50), np.linspace(1.0, 1500.0, 50)])[None, None, :]
    batch = screw.torque(preload, speed_rpm=speed, axial_load_n=axial, start="warm")
    assert batch.shape == (200, 5, 100) and batch.size == 100_000
    p, a, s = (x.ravel()[::97] for x in np.broadcast_arrays(preload, axial, speed))
    loop = np.array([screw.torque(float(x), float(y), float(z)) for x, y, z in zip(p, s, a)])
    np.testing.assert_allclose(batch.ravel()[::97], loop, rtol=1e-8, atol=0)
    # Without axial load the drag torque opposes the rotation: its sign is the speed's.
    assert np.all(np.sign(batch[:, 2, :]) == np.sign(speed[0]))
    # The canonical batch of a part of the grid is the scalar calls' bits.
    part = screw.torque(preload[::40], speed_rpm=speed[:, :, ::25], axial_load_n=axial[:, ::2])
    p, a, s = np.broadcast_arrays(preload[::40], axial[:, ::2], speed[:, :, ::25])
    loop = np.array([screw.torque(float(x), float(y), float(z)) for x, y, z in zip(p.ravel(), s.ravel(), a.ravel())])
    np.testing.assert_array_equal(part.ravel(), loop)
    with pytest.raises(ValueError, match=r'invalid start: "cold" \(valid: "canonical" or "warm"\)'):
        screw.torque(preload, start="cold")


def test_lubricated_batch_is_the_scalar_calls_to_the_bit(screw):
    # The lubricated default, 12 preloads x 3 axial loads x 24 speeds up to 1000 rpm in both
    # directions and through the standstill band (0.1 rpm).
    preload = np.linspace(500.0, 3000.0, 12)[:, None, None]
    axial = np.array([-300.0, 0.0, 250.0])[None, :, None]
    half = np.concatenate([[0.05], np.geomspace(0.5, 1000.0, 11)])
    speed = np.concatenate([-half[::-1], half])[None, None, :]
    batch = screw.torque(preload, speed_rpm=speed, axial_load_n=axial)
    p, a, s = np.broadcast_arrays(preload, axial, speed)
    loop = np.array([screw.torque(float(x), float(y), float(z)) for x, y, z in zip(p.ravel(), s.ravel(), a.ravel())])
    np.testing.assert_array_equal(batch.ravel(), loop)


def test_the_batch_releases_the_gil(screw, assert_releases_the_gil):
    # A batch long enough to watch (tenths of a second): points of random load and speed in
    # random order, each solved cold.
    fresh = ballscrew.Screw.from_toml_str(screw.to_toml())
    rng = np.random.default_rng(7)
    preload = rng.uniform(500.0, 3000.0, 800)
    speed = rng.uniform(1.0, 3000.0, 800) * rng.choice([-1.0, 1.0], 800)
    axial = rng.uniform(-500.0, 500.0, 800)
    assert_releases_the_gil(lambda: fresh.torque(preload, speed_rpm=speed, axial_load_n=axial))


def test_sweep_default_is_the_command_lines_preload_range(screw):
    table = screw.sweep(frame=False)
    assert list(table) == ["preload_n", "speed_rpm", "axial_load_n", "oil_temperature_c", "torque_nm", "drag_torque_nm", "load_torque_nm", "torque_energy_nm",
                           "torque_moment_nm", "torque_eq27_nm", "catalog_nm", "catalog_low_nm", "catalog_high_nm",
                           "ratio", "iterations", "max_residual", "forward_efficiency", "backdrive_efficiency",
                           "backdrive_torque_nm"]
    np.testing.assert_array_equal(table["preload_n"], np.arange(500.0, 3001.0, 100.0))
    # Every row names its whole operating point: the spec's speed, axial load and oil temperature.
    n = len(table["preload_n"])
    np.testing.assert_array_equal(table["speed_rpm"], np.full(n, 100.0))
    np.testing.assert_array_equal(table["axial_load_n"], np.zeros(n))
    np.testing.assert_array_equal(table["oil_temperature_c"], np.full(n, 40.0))
    other = screw.sweep([1000.0], speed_rpm=-250.0, axial_load_n=300.0, frame=False)
    # The speed reads back as given in rpm (not -249.99999999999997).
    assert (other["speed_rpm"][0], other["axial_load_n"][0]) == (-250.0, 300.0)
    assert table["iterations"].dtype.kind == "u" and table["torque_nm"].dtype == np.float64
    np.testing.assert_array_equal(table["torque_nm"], screw.torque(table["preload_n"]))
    # Energy and moment routes agree (docs/model.md: to 1e-6).
    np.testing.assert_allclose(table["torque_moment_nm"], table["torque_energy_nm"], rtol=1e-6)
    assert np.all(table["max_residual"] < 1e-6)


def test_sweep_at_another_speed_and_axial_load(screw):
    table = screw.sweep([1000.0, 2000.0], speed_rpm=-50.0, axial_load_n=200.0, frame=False)
    assert table["torque_nm"][1] == pytest.approx(screw.torque(2000.0, -50.0, 200.0), rel=1e-12)


def test_sweep_gives_a_dataframe_when_pandas_is_there(screw, monkeypatch):
    made = {}

    class DataFrame:
        def __init__(self, data):
            made["columns"] = list(data)
            made["data"] = data

    monkeypatch.setitem(sys.modules, "pandas", types.SimpleNamespace(DataFrame=DataFrame))
    frame = screw.sweep([1000.0, 2000.0])
    assert isinstance(frame, DataFrame) and made["columns"][:5] == [
        "preload_n", "speed_rpm", "axial_load_n", "oil_temperature_c", "torque_nm"]
    assert isinstance(screw.sweep([1000.0], frame=False), dict)


def test_sweep_without_pandas_gives_a_dict(screw, monkeypatch):
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas raises ImportError
    assert isinstance(screw.sweep([1000.0]), dict)
    with pytest.raises(ImportError):
        screw.sweep([1000.0], frame=True)


def test_inspect_adds_up_to_the_torque(screw):
    rows = screw.inspect(2000.0)
    assert [r["contact"] for r in rows[:3]] == ["nut", "screw", "ball-ball"]
    assert {(r["nut"], r["circle"]) for r in rows} == {(n, c) for n in (1, 2) for c in (1, 2, 3, 4)}
    summary = screw.summary(2000.0)
    # Energy route: T = F_a L / (2 pi) + sum of the contacts' shares + the return path's (no
    # axial load here).
    shares = sum(r["torque_share_nm"] for r in rows) + summary["return_torque_nm"]
    assert shares == pytest.approx(summary["torque_energy_nm"], rel=1e-12)
    assert summary["torque_nm"] == pytest.approx(screw.torque(2000.0), rel=1e-12)
    # Each circle's balls carry the nut's preload: sum of circle axial loads = 2000 N per nut.
    circles = {(r["nut"], r["circle"]): r["circle_axial_load_n"] for r in rows}
    for nut in (1, 2):
        assert sum(v for (n, _), v in circles.items() if n == nut) == pytest.approx(2000.0, rel=1e-12)


def test_everything_public_has_a_docstring():
    for name in ballscrew.__all__:
        obj = getattr(ballscrew, name)
        assert obj.__doc__ and len(obj.__doc__.strip()) > 20, name
    for name in dir(ballscrew.Screw):
        if not name.startswith("_"):
            assert getattr(ballscrew.Screw, name).__doc__, name


def test_scalar_calls_from_several_threads_agree_with_cold_evaluations(screw):
    preloads = [600.0, 1400.0, 2200.0, 2900.0]
    expected = {p: ballscrew.dkfzd4012_torque_nm(p) for p in preloads}
    results = {}

    def run(p):
        results[p] = [screw.torque(p) for _ in range(20)]

    threads = [threading.Thread(target=run, args=(p,)) for p in preloads]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for p in preloads:
        assert results[p] == pytest.approx([expected[p]] * 20, rel=1e-12)

"""The band of the drag torque from Python: Screw.band, Screw.sweep(band=...), Screw.sensitivity,
the spec's [uncertainty] through Screw.replace, and their errors."""

import os
import pickle
import signal
import sys
import threading
import time

import numpy as np
import pytest

import ballscrew

BAND_KEYS = ["drag_torque_low_nm", "drag_torque_median_nm", "drag_torque_high_nm"]
SENSITIVITY_KEYS = [
    "input", "key", "half_width", "half_width_unit", "low_end_nm", "high_end_nm", "swing_nm", "first_order", "total",
]
UNCERTAINTY_KEYS = [
    "viscosity_relative", "pressure_viscosity_relative", "temperature_k", "roughness_ball_relative",
    "roughness_raceway_relative", "boundary_friction", "full_film_traction", "preload_relative",
    "friction_coefficient_relative",
]


@pytest.fixture(scope="module")
def screw():
    return ballscrew.Screw.dkfzd4012()


@pytest.fixture(scope="module")
def pinned(screw):
    return screw.replace({f"uncertainty.{k}": 0.0 for k in UNCERTAINTY_KEYS})


def test_replace_takes_every_uncertainty_key_by_each_of_its_names(screw):
    for name in ["uncertainty.preload_relative", "uncertainty_preload_relative", "preload_relative"]:
        changed = screw.replace({name: 0.1})
        assert "preload_relative = 0.1" in changed.to_toml()
        assert ballscrew.Screw.from_toml_str(changed.to_toml()).to_toml() == changed.to_toml()
    # The default is written as no key at all; None goes back to it.
    assert "[uncertainty]" not in screw.to_toml()
    assert screw.replace(preload_relative=0.1).replace(preload_relative=None).to_toml() == screw.to_toml()
    with pytest.raises(ValueError, match=r"invalid uncertainty\.boundary_friction: 0\.6 \(valid: \[0, 0\.5\]\)"):
        screw.replace({"uncertainty.boundary_friction": 0.6})
    # A changed spread survives pickling.
    changed = screw.replace(temperature_k=2.0)
    assert pickle.loads(pickle.dumps(changed)).to_toml() == changed.to_toml()


def test_a_pinned_spec_has_a_band_of_zero_width_at_the_nominal(pinned):
    b = pinned.band(2000.0, 100.0)
    nominal = pinned.summary(2000.0, 100.0)["drag_torque_nm"]
    assert b == {"drag_torque_nm": nominal, **{k: nominal for k in BAND_KEYS}}
    # The same from a spec text with [uncertainty] all 0.
    text = pinned.to_toml()
    assert "[uncertainty]" in text
    assert ballscrew.Screw.from_toml_str(text).band(2000.0, 100.0) == b
    # Nothing spreads it: no rows of sensitivity.
    s = pinned.sensitivity(2000.0, 100.0, frame=False)
    assert list(s) == SENSITIVITY_KEYS and all(len(v) == 0 for v in s.values())
    assert s.attrs == {"drag_torque_nm": nominal, "variance_nm2": 0.0}


def test_the_band_of_dkfzd4012_contains_its_nominal_drag_torque(screw):
    b = screw.band(2000.0, 100.0)
    assert list(b) == ["drag_torque_nm", *BAND_KEYS]
    assert all(isinstance(v, float) for v in b.values())
    assert b["drag_torque_nm"] == screw.summary(2000.0, 100.0)["drag_torque_nm"]
    assert b["drag_torque_low_nm"] < b["drag_torque_nm"] < b["drag_torque_high_nm"]
    assert b["drag_torque_low_nm"] <= b["drag_torque_median_nm"] <= b["drag_torque_high_nm"]
    assert b["drag_torque_high_nm"] - b["drag_torque_low_nm"] > 0.0
    # The defaults are the ones the signature shows.
    assert screw.band(2000.0, 100.0, quantiles=(0.05, 0.95), samples=128, seed=0) == b
    # Wider quantiles, a wider band about the same median.
    wide = screw.band(2000.0, 100.0, quantiles=(0.0, 1.0))
    assert wide["drag_torque_median_nm"] == b["drag_torque_median_nm"]
    assert wide["drag_torque_low_nm"] < b["drag_torque_low_nm"] and wide["drag_torque_high_nm"] > b["drag_torque_high_nm"]


def test_arrays_give_arrays_of_the_broadcast_shape_each_point_as_alone(screw):
    preload = np.array([[1000.0], [2500.0]])
    speed = [30.0, 300.0, 1000.0]
    b = screw.band(preload, speed, samples=16)
    for k in ["drag_torque_nm", *BAND_KEYS]:
        assert b[k].shape == (2, 3) and b[k].dtype == np.float64
    alone = screw.band(2500.0, 300.0, samples=16)
    assert {k: v[1, 1] for k, v in b.items()} == alone
    assert b["drag_torque_nm"][0, 2] == screw.summary(1000.0, 1000.0)["drag_torque_nm"]


def test_the_same_seed_gives_the_same_band_and_another_seed_another(screw):
    p = np.linspace(500.0, 3000.0, 5)
    one = screw.band(p, 100.0, samples=32, seed=3)
    again = screw.band(p, 100.0, samples=32, seed=3)
    other = screw.band(p, 100.0, samples=32, seed=4)
    for k in BAND_KEYS:
        np.testing.assert_array_equal(one[k], again[k])
        assert not np.array_equal(one[k], other[k])
        np.testing.assert_allclose(one[k], other[k], rtol=0.1)
    np.testing.assert_array_equal(one["drag_torque_nm"], other["drag_torque_nm"])


def test_a_sweeps_band_columns_are_each_points_band_to_the_bit(screw):
    p = np.linspace(500.0, 3000.0, 6)
    table = screw.sweep(p, speed_rpm=300.0, band=True, samples=16, seed=2, frame=False)
    plain = screw.sweep(p, speed_rpm=300.0, frame=False)
    assert list(table) == [*plain, *BAND_KEYS]
    for k in plain:
        np.testing.assert_array_equal(table[k], plain[k])
    for i in [0, 3, 5]:
        b = screw.band(p[i], 300.0, samples=16, seed=2)
        assert [table[k][i] for k in BAND_KEYS] == [b[k] for k in BAND_KEYS]
        assert table["drag_torque_nm"][i] == pytest.approx(b["drag_torque_nm"], rel=1e-10)
    # A pair of quantiles is the band's.
    q = screw.sweep(p[:2], band=(0.25, 0.75), frame=False)
    b = screw.band(p[1], quantiles=(0.25, 0.75))
    assert [q[k][1] for k in BAND_KEYS] == [b[k] for k in BAND_KEYS]
    # band=False: no band columns.
    assert list(screw.sweep(p[:2], band=False, frame=False)) == list(plain)


def test_a_sweep_over_the_oil_temperature_has_each_temperatures_band(screw):
    t = [20.0, 60.0]
    table = screw.sweep(oil_temperature_c=t, band=True, samples=8, frame=False)
    for i, ti in enumerate(t):
        b = screw.with_oil_temperature(ti).band(samples=8)
        assert [table[k][i] for k in BAND_KEYS] == [b[k] for k in BAND_KEYS]


def test_a_sweeps_band_is_a_dataframes_last_columns(screw):
    pd = pytest.importorskip("pandas")
    df = screw.sweep([1000.0, 2000.0], band=True, samples=8)
    assert isinstance(df, pd.DataFrame) and list(df.columns[-3:]) == BAND_KEYS


def test_sensitivity_ranks_the_inputs_by_swing(screw):
    s = screw.sensitivity(2000.0, 100.0, frame=False)
    assert list(s) == SENSITIVITY_KEYS
    swing = s["swing_nm"]
    assert swing[0] == swing.max() and np.all(np.diff(swing) <= 0.0)
    np.testing.assert_array_equal(swing, np.abs(s["high_end_nm"] - s["low_end_nm"]))
    assert sum(s["first_order"]) <= 1.02
    # The dry model's friction coefficient is pinned by default and not read by the lubricated
    # model: every other input has a row.
    assert sorted(s["key"]) == sorted(f"uncertainty.{k}" for k in UNCERTAINTY_KEYS[:-1])
    assert all(isinstance(x, str) for x in s["input"] + s["half_width_unit"])
    assert s["half_width"][s["key"].index("uncertainty.temperature_k")] == 5.0
    assert s["half_width_unit"][s["key"].index("uncertainty.temperature_k")] == "K"
    assert s.attrs["drag_torque_nm"] == screw.summary(2000.0, 100.0)["drag_torque_nm"]
    assert s.attrs["variance_nm2"] > 0.0
    assert pickle.loads(pickle.dumps(s)).attrs == s.attrs
    # The same seed, the same numbers; each end is the drag torque with that input moved alone.
    again = screw.sensitivity(2000.0, 100.0, frame=False)
    for k in SENSITIVITY_KEYS:
        np.testing.assert_array_equal(np.asarray(again[k]), np.asarray(s[k]))
    i = s["key"].index("uncertainty.preload_relative")
    assert s["high_end_nm"][i] == pytest.approx(screw.summary(2600.0, 100.0)["drag_torque_nm"], rel=1e-9)
    assert s["low_end_nm"][i] == pytest.approx(screw.summary(1400.0, 100.0)["drag_torque_nm"], rel=1e-9)


def test_sensitivity_is_a_dataframe_with_attrs(screw):
    pd = pytest.importorskip("pandas")
    df = screw.sensitivity(2000.0, 100.0, samples=16)
    assert isinstance(df, pd.DataFrame) and list(df.columns) == SENSITIVITY_KEYS
    d = screw.sensitivity(2000.0, 100.0, samples=16, frame=False)
    assert df.attrs == d.attrs
    assert list(df["key"]) == d["key"]


@pytest.mark.parametrize(
    "call, message",
    [
        (lambda s: s.band(quantiles=(0.9, 0.1)), r"invalid band quantiles: 0\.9,0\.1 \(valid: two quantiles in \[0, 1\]"),
        (lambda s: s.band(quantiles=(0.1, 1.5)), r"invalid band quantiles: 0\.1,1\.5"),
        (lambda s: s.band(quantiles=(0.1,)), r"invalid band quantiles: \(0\.1,\)"),
        (lambda s: s.band(quantiles="ab"), r"invalid band quantiles: 'ab'"),
        (lambda s: s.band(samples=7), r"invalid band samples: 7 \(valid: a whole number in \[8, 65536\]\)"),
        (lambda s: s.band(samples=65537), r"invalid band samples: 65537 "),
        (lambda s: s.band(samples=-1), r"invalid band samples: -1 "),
        (lambda s: s.band(samples=64.0), r"invalid band samples: 64\.0 "),
        (lambda s: s.band(samples=True), r"invalid band samples: True "),
        (lambda s: s.band(seed=-1), r"invalid band seed: -1 \(valid: a whole number in \[0, 4294967295\]\)"),
        (lambda s: s.band(seed=2**32), r"invalid band seed: 4294967296 "),
        (lambda s: s.sensitivity(samples=4), r"invalid band samples: 4 "),
        (lambda s: s.sweep(band=(0.5, 0.5)), r"invalid band quantiles: 0\.5,0\.5"),
        (lambda s: s.sweep(band=True, samples=100000), r"invalid band samples: 100000 "),
        (lambda s: s.sweep(samples=64), r"^samples is given without band"),
        (lambda s: s.sweep(seed=1), r"^seed is given without band"),
        (lambda s: s.sweep(band=False, samples=64, seed=1), r"^samples and seed are given without band"),
        (lambda s: s.sensitivity([1000.0, 2000.0]), r"one operating point expected"),
    ],
)
def test_bad_settings_are_value_errors_naming_them(screw, call, message):
    with pytest.raises(ValueError, match=message):
        call(screw)


def test_a_spread_that_leaves_its_inputs_range_names_its_key(screw):
    # Boundary friction 0.12 +- 0.5 goes below 0; the oil at 40 C +- 50 K stays in [-30, 200] C,
    # at 180 C it does not.
    wide = screw.replace({"uncertainty.boundary_friction": 0.5})
    for call in [lambda: wide.band(2000.0), lambda: wide.sweep([2000.0], band=True), lambda: wide.sensitivity()]:
        with pytest.raises(ValueError, match=r"^invalid uncertainty\.boundary_friction: 0\.5 \(valid: a half-width that keeps"):
            call()
    hot = screw.replace(temperature_k=50.0)
    hot.band(samples=8)
    with pytest.raises(ValueError, match=r"^invalid uncertainty\.temperature_k: 50 "):
        hot.with_oil_temperature(180.0).band()


def test_a_point_the_spread_takes_beyond_the_models_reach_raises_as_torque_does(screw):
    # 3e5 N is within the static load capacity; 1.3 x 3e5 N (the preload's +30 %) is not.
    screw.torque(3e5)
    with pytest.raises(ValueError) as failing_torque:
        screw.torque(3.9e5)
    for call, where in [
        (lambda: screw.band(3e5, samples=8), r"at speed_rpm 100, preload_n 300000, axial_load_n 0$"),
        (lambda: screw.band([2000.0, 3e5], samples=8), r"\(index \(1,\) of the operating points\)$"),
        (lambda: screw.sweep([2000.0, 3e5], band=True, samples=8), r"\(row 1 of the sweep\)$"),
        (lambda: screw.sensitivity(3e5, samples=8), r"preload_n 300000, axial_load_n 0$"),
    ]:
        # The message names the input whose spread failed, at which end.
        said = r"preload at the high end of its spread \(uncertainty\.preload_relative\): .*peak Hertz pressure .*"
        with pytest.raises(ValueError, match=said + where) as e:
            call()
        assert type(e.value) is type(failing_torque.value)
    # Under errors="nan" a row the model cannot evaluate has a NaN band; the others have theirs.
    with pytest.warns(ballscrew.EvaluationWarning):
        table = screw.sweep([2000.0, 6e5], band=True, samples=8, errors="nan", frame=False)
    assert np.isnan(table["drag_torque_median_nm"][1])
    assert table["drag_torque_median_nm"][0] == screw.band(2000.0, samples=8)["drag_torque_median_nm"]


def test_the_band_releases_the_gil(screw, assert_releases_the_gil):
    assert_releases_the_gil(lambda: screw.band(np.linspace(500.0, 3000.0, 20), 100.0, samples=256))


@pytest.mark.skipif(sys.platform == "win32", reason="SIGINT by os.kill is POSIX")
def test_ctrl_c_ends_a_band(screw):
    # 2000 points by 128 samples: many seconds uninterrupted on two cores; SIGINT after 0.2 s.
    p = np.linspace(500.0, 3000.0, 2000)
    previous = signal.getsignal(signal.SIGINT)
    signal.signal(signal.SIGINT, signal.default_int_handler)
    timer = threading.Timer(0.2, os.kill, (os.getpid(), signal.SIGINT))
    start = time.perf_counter()
    timer.start()
    try:
        with pytest.raises(KeyboardInterrupt):
            screw.band(p, 100.0)
        assert time.perf_counter() - start < 1.0
    finally:
        timer.cancel()
        timer.join()
        signal.signal(signal.SIGINT, previous)
    assert screw.band(2000.0, samples=8) == screw.band(2000.0, samples=8)

"""errors="nan" on batches and sweeps: a point the model cannot evaluate costs one NaN, reported."""

import math
import warnings

import numpy as np
import pytest

import ballscrew

# Beyond the static load capacity: the model refuses the point (peak Hertz pressure above 6.3 GPa),
# whatever the arguments' own ranges allow.
BEYOND_N = 1e6
AXIAL = np.array([0.0, 150.0, BEYOND_N, 300.0, 450.0])


@pytest.fixture(scope="module")
def screw():
    return ballscrew.Screw.dkfzd4012()


def nan_mode(call):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        out = call()
    found = [w for w in caught if issubclass(w.category, ballscrew.EvaluationWarning)]
    assert len(found) <= 1
    return out, (found[0].message if found else None)


def test_the_point_beyond_the_capacity_raises_by_default(screw):
    with pytest.raises(ValueError, match=r"static load capacity.*index \(2,\)"):
        screw.torque(2000.0, axial_load_n=AXIAL)


def test_torque_gives_one_nan_and_the_raise_mode_values_elsewhere(screw):
    got, w = nan_mode(lambda: screw.torque(2000.0, axial_load_n=AXIAL, errors="nan"))
    want = screw.torque(2000.0, axial_load_n=np.delete(AXIAL, 2))
    assert np.isnan(got[2]) and np.count_nonzero(np.isnan(got)) == 1
    np.testing.assert_allclose(np.delete(got, 2), want, rtol=1e-12)
    assert (w.count, w.total, w.first_index) == (1, 5, 2)
    assert "static load capacity" in w.first_error and "axial_load_n 1000000" in w.first_error
    assert str(w).startswith('1 of 5 points could not be evaluated and gave NaN (errors="nan"); the first: ')
    assert issubclass(ballscrew.EvaluationWarning, RuntimeWarning)


def test_no_warning_when_every_point_is_evaluated(screw):
    got, w = nan_mode(lambda: screw.torque([1000.0, 2000.0], errors="nan"))
    assert w is None and np.array_equal(got, screw.torque([1000.0, 2000.0]))


def test_a_scalar_gives_nan_too(screw):
    got, w = nan_mode(lambda: screw.torque(2000.0, axial_load_n=BEYOND_N, errors="nan"))
    assert math.isnan(got) and (w.count, w.total) == (1, 1)


def test_bad_arguments_still_raise(screw):
    with pytest.raises(ValueError, match="invalid axial_load_n: NaN"):
        screw.torque(2000.0, axial_load_n=[0.0, math.nan], errors="nan")
    with pytest.raises(ValueError, match=r'invalid errors: "ignore" \(valid: "raise" or "nan"\)'):
        screw.torque(2000.0, errors="ignore")
    with pytest.raises(ValueError, match="invalid errors"):
        screw.sweep([1000.0], errors="coerce")


def test_sweep_gives_a_row_of_nan_with_its_operating_point(screw):
    preloads = [1000.0, 2000.0, 3000.0]
    fine = screw.sweep(preloads, axial_load_n=300.0, frame=False)
    with pytest.raises(ValueError, match="static load capacity"):
        screw.sweep(preloads, axial_load_n=BEYOND_N, frame=False)
    got, w = nan_mode(lambda: screw.sweep(preloads, axial_load_n=BEYOND_N, frame=False, errors="nan"))
    assert (w.count, w.total) == (3, 3)
    assert list(got) == list(fine)
    assert np.array_equal(got["preload_n"], preloads) and np.all(got["axial_load_n"] == BEYOND_N)
    assert np.all(np.isnan(got["torque_nm"])) and np.all(np.isnan(got["iterations"]))


def test_sweep_over_the_oil_temperature_keeps_the_good_points(screw):
    # Under a load beyond the capacity at any temperature every point fails; at a load within it
    # none does: both in one call show the count.
    temps = np.array([30.0, 50.0])
    ok = screw.sweep(2000.0, oil_temperature_c=temps, frame=False)
    got, w = nan_mode(lambda: screw.sweep(2000.0, oil_temperature_c=temps, frame=False, errors="nan"))
    assert w is None and np.array_equal(got["torque_nm"], ok["torque_nm"])
    got, w = nan_mode(lambda: screw.sweep(2000.0, axial_load_n=BEYOND_N, oil_temperature_c=temps, frame=False,
                                          errors="nan"))
    assert w.count == 2 and np.all(np.isnan(got["torque_nm"]))
    assert np.array_equal(got["oil_temperature_c"], temps)


def test_sweep_with_one_bad_point_matches_the_others(screw):
    # A preload of 1e6 N is a valid argument but beyond the screw's static capacity.
    got, w = nan_mode(lambda: screw.sweep([1000.0, BEYOND_N, 2000.0], frame=False, errors="nan"))
    want = screw.sweep([1000.0, 2000.0], frame=False)
    assert (w.count, w.total, w.first_index) == (1, 3, 1) and "index (1,)" in w.first_error
    assert np.array_equal(got["preload_n"], [1000.0, BEYOND_N, 2000.0])
    for key in ("torque_nm", "drag_torque_nm", "catalog_nm", "iterations"):
        assert np.isnan(got[key][1]), key
    # Warm-started from another point than in the plain sweep: equal to the solver's tolerance.
    np.testing.assert_allclose(got["torque_nm"][[0, 2]], want["torque_nm"], rtol=1e-9)
    assert got["iterations"].dtype.kind == "f" and got["iterations"][0] == want["iterations"][0]


def test_a_sweep_frame_has_nan_rows_too(screw):
    pd = pytest.importorskip("pandas")
    got, w = nan_mode(lambda: screw.sweep([1000.0, 2000.0], axial_load_n=BEYOND_N, errors="nan"))
    assert isinstance(got, pd.DataFrame) and got["torque_nm"].isna().all() and w.count == 2


@pytest.mark.parametrize("precision", ["f64", "f32"])
def test_evaluator_series_gives_one_nan_and_the_raise_mode_values_elsewhere(screw, precision):
    ev = ballscrew.Evaluator(screw, precision)
    with pytest.raises(ValueError, match="static load capacity"):
        ev.series(2000.0, axial_load_n=AXIAL)
    ev.reset()
    got, w = nan_mode(lambda: ev.series(2000.0, axial_load_n=AXIAL, errors="nan"))
    ev.reset()
    want = np.array([ev.torque(2000.0, axial_load_n=a) for a in np.delete(AXIAL, 2)])
    assert np.isnan(got[2]) and np.count_nonzero(np.isnan(got)) == 1
    tol = 1e-8 if precision == "f64" else 1e-4
    np.testing.assert_allclose(np.delete(got, 2), want, rtol=tol)
    assert (w.count, w.total, w.first_index) == (1, 5, 2)


def test_predict_gives_one_nan_per_failing_row(screw):
    data = {"preload_n": [2000.0] * 5, "axial_load_n": AXIAL}
    with pytest.raises(ValueError, match="data row 3: .*static load capacity"):
        ballscrew.predict(data)
    got, w = nan_mode(lambda: ballscrew.predict(data, errors="nan"))
    assert np.isnan(got[2]) and np.count_nonzero(np.isnan(got)) == 1
    want = ballscrew.predict({"preload_n": [2000.0] * 4, "axial_load_n": np.delete(AXIAL, 2)})
    np.testing.assert_allclose(np.delete(got, 2), want, rtol=1e-12)
    assert (w.count, w.total, w.first_index) == (1, 5, 2) and w.first_error.startswith("data row 3: ")
    assert str(w).startswith("1 of 5 rows could not be evaluated")


def test_the_warning_points_at_the_callers_line(screw):
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        screw.torque(2000.0, axial_load_n=AXIAL, errors="nan")
    assert caught[0].filename == __file__

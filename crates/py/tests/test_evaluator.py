"""The Evaluator class: the control-loop evaluator in f64 and f32 against Screw.torque, series
as a warm-started time series, broadcasting, reset, errors and threads."""

import inspect
import math
import pathlib
import warnings
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import pytest

import ballscrew

# Agreement with the analysis model (Screw.torque, solved to 1e-12): the evaluator's documented
# accuracy (docs/real-time.md, "The control-loop evaluator"): f64 within 1e-8, f32 within 1e-4, relative.
RTOL = {"f64": 1e-8, "f32": 1e-4}


@pytest.fixture(scope="module")
def screw():
    return ballscrew.Screw.dkfzd4012()


@pytest.fixture(scope="module", params=["f64", "f32"])
def precision(request):
    return request.param


def fastsim_text(screw):
    text = screw.to_toml()
    assert 'contact_theory = "linear-saturated"' in text
    return text.replace('contact_theory = "linear-saturated"', 'contact_theory = "fastsim"')


def test_properties(screw, precision):
    ev = ballscrew.Evaluator(screw, precision)
    assert ev.precision == precision
    assert ev.tolerance == pytest.approx({"f64": 1e-9, "f32": 1e-5}[precision], rel=1e-6)
    assert ballscrew.Evaluator(screw).precision == "f64"
    assert precision in repr(ev)
    with pytest.raises(AttributeError):
        ev.precision = "f32"


def test_agrees_with_screw_torque_over_a_preload_sweep(screw, precision):
    ev = ballscrew.Evaluator(screw, precision=precision)
    up = np.linspace(100.0, 5000.0, 50)
    # Up, then down again in smaller steps (warm starts), then a few jumps (table starts).
    preloads = np.concatenate([up, np.linspace(5000.0, 100.0, 200), [3000.0, 250.0, 4200.0, 900.0]])
    for axial in (0.0, 400.0):
        got = np.array([ev.torque(float(p), axial_load_n=axial) for p in preloads])
        want = np.array([screw.torque(float(p), axial_load_n=axial) for p in preloads])
        np.testing.assert_allclose(got, want, rtol=RTOL[precision], atol=0)
        assert np.all(got > 0.0)


def test_agrees_through_speed_reversals_and_standstill(screw, precision):
    ev = ballscrew.Evaluator(screw, precision)
    standstill = screw.standstill_speed_rpm  # 0.1 rpm: the creep forces fade below it
    ramp = [100.0, 30.0, 1.0, standstill, 0.5 * standstill, 0.1 * standstill, 0.0]
    speeds = ramp + [-s for s in reversed(ramp)] + [-100.0, 100.0, -100.0, 0.0, 0.0, 2.0 * standstill, 300.0]
    scale = abs(screw.torque(2000.0))
    for axial in (0.0, -250.0):
        got = [ev.torque(2000.0, s, axial) for s in speeds]
        want = [screw.torque(2000.0, speed_rpm=s, axial_load_n=axial) for s in speeds]
        for s, g, w in zip(speeds, got, want):
            assert g == pytest.approx(w, rel=RTOL[precision], abs=RTOL[precision] * 1e-3 * scale), s
    # The torque opposes the rotation without axial load and vanishes at standstill.
    assert ev.torque(2000.0, -100.0) < 0.0 < ev.torque(2000.0, 100.0)
    assert ev.torque(2000.0, 0.0) == 0.0


def test_extension_terms_as_screw_torque(screw, precision):
    text = screw.to_toml() + (
        "\n[extensions.seal_drag]\ntorque_nm = 0.01\n"
        "\n[extensions.viscous_drag]\ntorque_nm = 0.02\nexponent = 0.5\n"
    )
    extended = ballscrew.Screw.from_toml_str(text, origin="with seals")
    ev = ballscrew.Evaluator(extended, precision)
    for p, s in [(2000.0, 100.0), (2000.0, 900.0), (800.0, -400.0), (800.0, 0.0)]:
        want = extended.torque(p, speed_rpm=s)
        assert ev.torque(p, s) == pytest.approx(want, rel=RTOL[precision]), (p, s)
    # The terms are there: above the bare model's torque.
    assert ev.torque(2000.0, 900.0) > screw.torque(2000.0, speed_rpm=900.0) + 0.02


def test_defaults_are_the_specs_operating_point(screw, precision):
    ev = ballscrew.Evaluator(screw, precision)
    other = ballscrew.Evaluator(screw, precision)
    assert ev.torque(1500.0) == other.torque(1500.0, screw.default_speed_rpm, screw.default_axial_load_n)
    assert ev.torque(1500.0) == pytest.approx(screw.torque(1500.0), rel=RTOL[precision])


def test_series_equals_scalar_calls_in_the_same_order(screw, precision):
    preload = np.linspace(500.0, 3000.0, 30)[:, None]
    speed = np.array([100.0, 0.05, 0.0, -0.05, -100.0, -3.0])  # reversals inside each row
    axial = 150.0
    series = ballscrew.Evaluator(screw, precision).series(preload, speed_rpm=speed, axial_load_n=axial)
    assert series.shape == (30, 6) and series.dtype == np.float64
    ev = ballscrew.Evaluator(screw, precision)
    p, s = np.broadcast_arrays(preload, speed)
    loop = np.array([ev.torque(float(x), float(y), axial) for x, y in zip(p.ravel(), s.ravel())])
    # Exactly: the same points through the same state sequence.
    np.testing.assert_array_equal(series.ravel(), loop)
    # The evaluator's tolerance is on the balls' force imbalance over their load: its torque
    # error scales with the running friction torque, not with a net torque in which the axial
    # load's torque cancels the friction (slow reversed points here) or with the standstill
    # band's fraction of it. So the error is also counted against the running torque.
    np.testing.assert_allclose(
        series, screw.torque(preload, speed_rpm=speed, axial_load_n=axial), rtol=RTOL[precision],
        atol=RTOL[precision] * abs(screw.torque(3000.0)),
    )


def test_series_continues_and_updates_the_state(screw, precision):
    first = np.linspace(1000.0, 1100.0, 40)
    second = np.linspace(1100.0, 1200.0, 40)
    whole = ballscrew.Evaluator(screw, precision).series(np.concatenate([first, second]))
    ev = ballscrew.Evaluator(screw, precision)
    np.testing.assert_array_equal(np.concatenate([ev.series(first), ev.series(second)]), whole)
    # A scalar call after a series warm-starts from the series' last point, and the other way.
    ev_a, ev_b = ballscrew.Evaluator(screw, precision), ballscrew.Evaluator(screw, precision)
    ev_a.series(first)
    for p in first:
        ev_b.torque(float(p))
    assert ev_a.torque(1100.5) == ev_b.torque(1100.5)
    assert ev_a.series(1101.0) == ev_b.series(1101.0)
    # Numbers or 0-d arrays give a float, as `Screw.torque` does; a 1-element array an array.
    for one in (1102.0, np.float64(1102.0), np.array(1102.0)):
        got = ev_a.series(one, speed_rpm=np.array(100.0))
        assert type(got) is float and got == ev_b.torque(1102.0, speed_rpm=100.0), one
        assert type(screw.torque(one, speed_rpm=np.array(100.0))) is float
    assert ev_a.series(np.array([1102.0])).shape == (1,)


@pytest.mark.parametrize(
    "preload, speed, axial, shape",
    [
        (2000.0, None, None, ()),
        (np.array(2000.0), None, None, ()),
        ([500.0, 1000.0, 2000.0], None, None, (3,)),
        (2000.0, [100.0, -100.0], None, (2,)),
        (np.linspace(500.0, 3000.0, 4)[:, None], [100.0, 0.0, -100.0], None, (4, 3)),
        ([[1000.0], [2000.0]], None, np.array([[[-100.0, 0.0, 100.0]]]), (1, 2, 3)),
        (np.empty(0), None, None, (0,)),
    ],
)
def test_series_broadcasts_to_numpys_shape(screw, preload, speed, axial, shape):
    kwargs = {k: v for k, v in (("speed_rpm", speed), ("axial_load_n", axial)) if v is not None}
    out = ballscrew.Evaluator(screw).series(preload, **kwargs)
    if shape == ():
        # Numbers and 0-d arrays give a float, as from `Screw.torque`.
        assert type(out) is float and type(screw.torque(preload, **kwargs)) is float
    else:
        assert isinstance(out, np.ndarray) and out.dtype == np.float64 and out.shape == shape
    np.testing.assert_allclose(out, screw.torque(preload, **kwargs), rtol=1e-8, atol=1e-12)


def test_series_refuses_shapes_that_do_not_broadcast(screw):
    with pytest.raises(ValueError, match=r"do not broadcast.*preload_n \(3,\).*speed_rpm \(2,\)"):
        ballscrew.Evaluator(screw).series([1000.0, 2000.0, 3000.0], speed_rpm=[100.0, -100.0])


def test_reset_forgets_the_warm_state(screw, precision):
    # A ramp in steps under 1 % of the load: every point after the first is warm-started from the
    # ones before, so its result depends on them (to the solver's tolerance, not bit for bit).
    ramp = np.linspace(2000.0, 2030.0, 31)
    cold = ballscrew.Evaluator(screw, precision).series(ramp)
    ev = ballscrew.Evaluator(screw, precision)
    ev.series(ramp[::-1])
    warm = ev.series(ramp)
    assert not np.array_equal(warm, cold)  # the history changed the start of each solve
    np.testing.assert_allclose(warm, cold, rtol=RTOL[precision])
    ev.reset()
    np.testing.assert_array_equal(ev.series(ramp), cold)


@pytest.mark.parametrize("bad", ["f16", "F64", "double", "", 64, 3.0])
def test_bad_precision_is_a_value_error_naming_it(screw, bad):
    with pytest.raises(ValueError, match=r"invalid precision: .* \(valid: \"f64\", \"f32\"\)"):
        ballscrew.Evaluator(screw, bad)


@pytest.mark.parametrize(
    "kwargs, name",
    [
        (dict(preload_n=math.nan), "preload_n"),
        (dict(preload_n=-5.0), "preload_n"),
        (dict(preload_n=1e12), "preload_n"),
        (dict(preload_n=2000.0, speed_rpm=math.inf), "speed_rpm"),
        (dict(preload_n=2000.0, speed_rpm=-1e6), "speed_rpm"),
        (dict(preload_n=2000.0, axial_load_n=math.nan), "axial_load_n"),
        (dict(preload_n=2000.0, axial_load_n=-math.inf), "axial_load_n"),
        (dict(preload_n="2000"), "preload_n"),
    ],
)
def test_bad_points_are_value_errors_naming_the_argument(screw, precision, kwargs, name):
    ev = ballscrew.Evaluator(screw, precision)
    with pytest.raises(ValueError, match=rf"invalid {name}: .*\(valid: "):
        ev.torque(**kwargs)
    with pytest.raises(ValueError, match=rf"invalid {name}: "):
        ev.series(**kwargs)
    # Still usable afterwards.
    assert ev.torque(2000.0) == pytest.approx(screw.torque(2000.0), rel=RTOL[precision])


def test_bad_point_in_a_series_names_its_index_and_computes_nothing(screw):
    ev = ballscrew.Evaluator(screw)
    preload = np.array([[1000.0, 2000.0], [3000.0, np.nan]])
    with pytest.raises(ValueError, match=r"invalid preload_n: NaN .* at index \(1, 1\)"):
        ev.series(preload)
    with pytest.raises(ValueError, match=r"invalid speed_rpm: 40000 .* at index \(2,\)"):
        ev.series(2000.0, speed_rpm=[100.0, 0.0, 40000.0])
    # Nothing was evaluated: the state is still empty, so the next series is a cold one.
    np.testing.assert_array_equal(ev.series([1000.0, 1001.0]), ballscrew.Evaluator(screw).series([1000.0, 1001.0]))


def test_no_quasi_static_state_is_a_convergence_error(screw, precision):
    # docs/prediction.md: from about 15 N of ball-ball load on, the lightest circle's balls skid; at 16 N
    # the balance has a solution again from a preload of a few kN on (dry model).
    text = screw.to_toml().replace('lubrication = "ehl"', 'lubrication = "dry"')
    # The built-in spec leaves the load between balls to the ball train; set it (the paper's
    # parameter).
    assert "ball_ball_load_n" not in text
    skid = ballscrew.Screw.from_toml_str(text.replace("[friction]\n", "[friction]\nball_ball_load_n = 16.0\n", 1))
    ev = ballscrew.Evaluator(skid, precision)
    with pytest.raises(ballscrew.ConvergenceError, match=r"did not converge .* preload_n 2000"):
        ev.torque(2000.0)
    with pytest.raises(ballscrew.ConvergenceError, match=r"did not converge .* preload_n 1000, .*index \(1,\)"):
        ev.series([5000.0, 1000.0, 10000.0])
    # Still usable afterwards, at a point that has a solution.
    assert ev.torque(10000.0) == pytest.approx(skid.torque(10000.0), rel=RTOL[precision])


def test_torque_takes_one_point_only(screw):
    with pytest.raises(ValueError, match=r"one operating point expected.*shape \(2,\)"):
        ballscrew.Evaluator(screw).torque([1000.0, 2000.0])


def test_fastsim_specs_run_on_the_model_in_f64_and_are_refused_in_f32(screw):
    fastsim = ballscrew.Screw.from_toml_str(fastsim_text(screw), origin="fastsim spec")
    assert fastsim.contact_theory == "fastsim"
    with pytest.raises(
        ValueError, match=r'precision "f32" needs the control-loop evaluator.*model\.contact_theory: fastsim'
    ):
        ballscrew.Evaluator(fastsim, "f32")
    ev = ballscrew.Evaluator(fastsim)
    assert (ev.solver, ev.precision, ev.tolerance) == ("model", "f64", 1e-12)
    # The model's own solve, warm-started: Screw.torque's torques (each solved to 1e-12 from
    # its own warm start, so to the solver's tolerance, not bit for bit).
    points = [(1500.0, 300.0, 0.0), (1500.0, -300.0, 200.0), (2500.0, 100.0, -300.0)]
    for p, s, a in points:
        assert ev.torque(p, speed_rpm=s, axial_load_n=a) == pytest.approx(
            fastsim.torque(p, speed_rpm=s, axial_load_n=a), rel=1e-8
        )
    assert ballscrew.Evaluator(screw).solver == "evaluator"


def test_needs_a_screw():
    with pytest.raises(TypeError):
        ballscrew.Evaluator("dkfzd4012")


def test_signature_shows_the_default_precision():
    params = inspect.signature(ballscrew.Evaluator).parameters
    assert list(params) == ["screw", "precision", "audit_every"] and params["precision"].default == "f64"
    assert params["audit_every"].default == 1000 and params["audit_every"].kind is inspect.Parameter.KEYWORD_ONLY


def test_every_member_has_a_docstring():
    assert ballscrew.Evaluator.__doc__ and "rpm" in ballscrew.Evaluator.__doc__
    for name in dir(ballscrew.Evaluator):
        if not name.startswith("_"):
            assert getattr(ballscrew.Evaluator, name).__doc__, name
    for name in ("torque", "series"):
        doc = getattr(ballscrew.Evaluator, name).__doc__
        assert "N m" in doc and "rpm" in doc and "(N)" in doc, name


def test_one_evaluator_shared_by_threads(screw):
    ev = ballscrew.Evaluator(screw)
    preloads = [600.0, 1400.0, 2200.0, 2900.0] * 2

    def run(p):
        return [ev.torque(p) for _ in range(20)] + list(ev.series(np.full(20, p)))

    with ThreadPoolExecutor(max_workers=len(preloads)) as pool:
        results = list(pool.map(run, preloads))
    for p, got in zip(preloads, results):
        assert got == pytest.approx([screw.torque(p)] * 40, rel=1e-8), p


def test_series_releases_the_gil(screw, assert_releases_the_gil):
    ev = ballscrew.Evaluator(screw)
    # Steps of about 0.1 % in load: warm starts, microseconds a point, about 0.2 s in all.
    points = np.tile(np.concatenate([np.linspace(1000.0, 2000.0, 1000), np.linspace(2000.0, 1000.0, 1000)]), 50)
    assert_releases_the_gil(lambda: ev.series(points))


SINGLE_NUT = pathlib.Path(__file__).resolve().parents[3] / "configs" / "single-nut-16x5.toml"


def test_a_departure_from_the_canonical_state_is_said():
    # The single nut 16 x 5 (its oversize balls run on the model's warm solve) at 200 N of
    # preload and 3550 N of axial load, speeding up in reverse: at -100 rpm the warm solve sits
    # on another steady state, about 2 % of the drag torque from the cold solve (the canonical
    # state, what Screw.torque gives). Audited at every call, the evaluator says so.
    screw = ballscrew.Screw.from_toml(SINGLE_NUT)
    speeds = [0.0, -10.0, -25.0, -50.0, -75.0, -100.0]
    ev = ballscrew.Evaluator(screw, audit_every=1)
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        warm = ev.series(200.0, speed_rpm=speeds, axial_load_n=3550.0)
    states = [w.message for w in caught if isinstance(w.message, ballscrew.StateWarning)]
    assert len(states) == 1, [str(w.message) for w in caught]
    w = states[0]
    canonical = screw.torque(200.0, speed_rpm=-100.0, axial_load_n=3550.0)
    assert (w.count, w.first_index, w.speed_rpm, w.preload_n, w.axial_load_n) == (1, 5, -100.0, 200.0, 3550.0)
    assert w.torque_nm == warm[5] and w.canonical_torque_nm == canonical
    drag = screw.summary(200.0, speed_rpm=-100.0, axial_load_n=3550.0)["drag_torque_nm"]
    assert w.relative_departure == pytest.approx(abs(warm[5] - canonical) / abs(drag), rel=1e-12)
    assert w.relative_departure > 1e-3
    # The numbers docs/real-time.md ("Saying so") gives.
    assert (round(w.torque_nm, 5), round(canonical, 5), round(w.relative_departure, 4)) == (2.67721, 2.67998, 0.0191)
    assert "canonical state" in str(w) and "index (5,)" in str(w) and "more than 1e-6 of the drag torque" in str(w)
    a = ev.audit
    assert (a["audit_every"], a["calls"], a["audited"], a["departed"]) == (1, 6, 6, 1)
    assert a["tolerance"] == 1e-6 and a["largest_departure"] == w.relative_departure
    assert a["first_departure"]["speed_rpm"] == -100.0 and a["first_departure"]["torque_nm"] == warm[5]
    ev.reset()
    assert (ev.audit["calls"], ev.audit["departed"], ev.audit["first_departure"]) == (0, 0, None)
    # By default the first call and every 1000th after it are audited: here the first only.
    quiet = ballscrew.Evaluator(screw)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ballscrew.StateWarning)
        np.testing.assert_array_equal(quiet.series(200.0, speed_rpm=speeds, axial_load_n=3550.0), warm)
    assert (quiet.audit["calls"], quiet.audit["audited"], quiet.audit["departed"]) == (6, 1, 0)


def test_an_audit_on_the_built_in_screw_finds_no_departure(screw, precision):
    ev = ballscrew.Evaluator(screw, precision=precision, audit_every=5)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ballscrew.StateWarning)
        ev.series(np.linspace(500.0, 3000.0, 40), speed_rpm=np.linspace(-300.0, 300.0, 40), axial_load_n=100.0)
    a = ev.audit
    assert (a["calls"], a["audited"], a["departed"]) == (40, 8, 0)
    assert 0.0 < a["largest_departure"] <= a["tolerance"] == (1e-6 if precision == "f64" else 5e-4)


@pytest.mark.parametrize("bad", [-1, 1.5, "10", 2**32])
def test_bad_audit_every_is_a_value_error_naming_it(screw, bad):
    with pytest.raises(ValueError, match=r"invalid audit_every: .* \(valid: a whole number in \[0, 4294967295\]"):
        ballscrew.Evaluator(screw, audit_every=bad)


def test_the_audit_changes_no_torque_and_takes_standstill_under_a_load(screw, precision):
    # An audit solves cold beside the warm state and changes nothing: audited at every point or
    # not at all, the same bits. Through standstill under an axial load the drag is zero and
    # the torque the load's, whose rounding in f32 is no departure.
    speeds = np.concatenate([np.linspace(300.0, 0.0, 16), np.zeros(4), np.linspace(0.0, -300.0, 16)])
    every = ballscrew.Evaluator(screw, precision=precision, audit_every=1)
    none = ballscrew.Evaluator(screw, precision=precision, audit_every=0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", ballscrew.StateWarning)
        audited = every.series(2000.0, speed_rpm=speeds, axial_load_n=300.0)
    np.testing.assert_array_equal(audited, none.series(2000.0, speed_rpm=speeds, axial_load_n=300.0))
    assert (every.audit["audited"], every.audit["departed"], none.audit["audited"]) == (36, 0, 0)

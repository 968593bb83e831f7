"""The Reversal class: the friction state through reversals (presliding) against Screw.torque at
constant speed, series as repeated steps, independence of the step size, passivity, reset,
properties and errors."""

import inspect
import math
import warnings

import numpy as np
import pytest

import ballscrew

# Agreement with the analysis model at constant speed: the evaluator's accuracy (f64 within
# 1e-8, f32 within 1e-4, relative), which sets each circle's steady friction.
RTOL = {"f64": 1e-8, "f32": 1e-4}


def rad_s(rpm):
    return rpm * 2.0 * math.pi / 60.0


@pytest.fixture(scope="module")
def screw():
    return ballscrew.Screw.dkfzd4012()


@pytest.fixture(scope="module")
def model(screw):
    """model(precision="f64", preload_n=2000.0, axial_load_n=0.0): one Reversal per arguments for
    the module (a fraction of a second to build), reset to the relaxed state."""
    built = {}

    def get(precision="f64", preload_n=2000.0, axial_load_n=0.0):
        key = (precision, preload_n, axial_load_n)
        if key not in built:
            built[key] = ballscrew.Reversal(screw, preload_n, axial_load_n, precision)
        built[key].reset()
        return built[key]

    return get


@pytest.fixture(scope="module", params=["f64", "f32"])
def precision(request):
    return request.param


def test_properties(screw, model, precision):
    rev = model(precision)
    assert rev.precision == precision
    assert (rev.preload_n, rev.axial_load_n) == (2000.0, 0.0)
    assert rev.stiffness_nm_per_rad > 0.0
    # One stiffness for both directions, also under an axial load (passivity).
    assert model(precision, 2000.0, 300.0).stiffness_nm_per_rad > 0.0
    assert rev.friction_nm == 0.0
    assert repr(rev) == f"<ballscrew.Reversal in {precision} at preload_n 2000, axial_load_n 0; friction_nm 0>"
    for name in ("precision", "preload_n", "stiffness_nm_per_rad", "friction_nm"):
        with pytest.raises(AttributeError):
            setattr(rev, name, 1.0)


def test_defaults_are_the_specs_operating_point(screw):
    rev = ballscrew.Reversal(screw)
    assert rev.precision == "f64"
    assert (rev.preload_n, rev.axial_load_n) == (screw.default_preload_n, screw.default_axial_load_n)


@pytest.mark.parametrize("preload, axial", [(2000.0, 0.0), (1000.0, 300.0)])
def test_constant_speed_gives_screw_torque(screw, model, precision, preload, axial):
    rev = model(precision, preload, axial)
    dt = 1e-3
    for rpm in (100.0, -1000.0, 30.0):
        want = screw.torque(preload, speed_rpm=rpm, axial_load_n=axial)
        rev.reset(speed_rpm=rpm)
        got = [rev.step(rad_s(rpm) * dt, dt) for _ in range(10)]
        np.testing.assert_allclose(got, want, rtol=RTOL[precision], atol=0)
        # From rest, after a few hundred relaxation angles of rotation (0.2 rad here).
        rev.reset()
        got = rev.series(np.full(200, rad_s(rpm) * dt), dt)[-1]
        assert got == pytest.approx(want, rel=RTOL[precision]), rpm


def reversal_path(amplitude_rad, peak_rpm, steps):
    """theta = A sin(Omega t) from its zero crossing at the peak speed to the next one, in
    `steps` equal time steps: the rotation of each step (rad) and the time step (s)."""
    peak = rad_s(peak_rpm)
    omega = peak / amplitude_rad
    dt = math.pi / omega / steps
    theta = amplitude_rad * np.sin(omega * dt * np.arange(1, steps + 1))
    return np.diff(theta, prepend=0.0), dt


def test_series_equals_steps_bit_for_bit(model, precision):
    rotation, dt = reversal_path(0.002, 10.0, 200)
    # Two rows of the same reversal, the second with half the time steps: (2, 200) by broadcast.
    dts = np.array([[dt], [0.5 * dt]])
    rev = model(precision)
    rev.reset(speed_rpm=10.0)
    series = rev.series(rotation, dts)
    assert series.shape == (2, 200) and series.dtype == np.float64
    held = rev.friction_nm
    rev.reset(speed_rpm=10.0)
    r, d = np.broadcast_arrays(rotation, dts)
    steps = np.array([rev.step(float(x), float(y)) for x, y in zip(r.ravel(), d.ravel())])
    np.testing.assert_array_equal(series.ravel(), steps)
    assert rev.friction_nm == held
    # A series continues from the state: two halves equal the whole.
    rev.reset(speed_rpm=10.0)
    halves = np.concatenate([rev.series(rotation[:77], dt), rev.series(rotation[77:], dt)])
    rev.reset(speed_rpm=10.0)
    np.testing.assert_array_equal(halves, rev.series(rotation, dt))
    # Scalars give a 0-d array, an empty series an empty one.
    assert rev.series(1e-5, 1e-3).shape == ()
    assert rev.series(np.empty((0, 3)), 1e-3).shape == (0, 3)


def test_a_reversal_does_not_depend_on_the_step(screw, model):
    """A reversal at 10 rpm peak speed, of an amplitude of 11 relaxation angles (g / sigma,
    2.7e-4 rad), stepped at most 1e-4 and 1e-6 rad: the torques at the common times agree within
    1 % of the steady torque."""
    rev = model()
    amplitude, peak_rpm = 0.003, 10.0
    coarse_steps = round(math.pi * amplitude / 1e-4)  # the largest step turns 1e-4 rad
    out = {}
    for stride in (1, 100):
        rotation, dt = reversal_path(amplitude, peak_rpm, coarse_steps * stride)
        rev.reset(speed_rpm=peak_rpm)
        out[stride] = rev.series(rotation, dt)[stride - 1 :: stride]
    coarse, fine = out[1], out[100]
    steady = screw.torque(2000.0, speed_rpm=peak_rpm)
    worst = np.max(np.abs(coarse - fine))
    assert worst <= 0.01 * steady, f"{worst:.3e} N m against {steady:.4f} N m"
    # The torque does reverse, from the forwards to the backwards steady value.
    assert coarse[0] > 0.9 * steady and coarse[-1] == pytest.approx(-steady, rel=1e-2)
    # Not at once (presliding): after the turning point the torque still holds the forwards
    # friction, and it crosses zero after a back rotation no shorter than Dahl's ln(2) g / sigma
    # (from the relaxed friction g, stiffness sigma) and within a milliradian (1.9e-4 rad here:
    # most of sigma is now the ball-ball contacts', which carry under 1 % of g and saturate
    # within nanoradians; the raceways' slower mechanisms set the crossing).
    rotation, _ = reversal_path(amplitude, peak_rpm, coarse_steps)
    theta = np.cumsum(rotation)
    first_back = int(np.argmax(rotation < 0.0))
    assert coarse[first_back] > 0.9 * steady
    crossing = int(np.argmax(coarse < 0.0))
    back = theta.max() - theta[crossing]
    dahl = math.log(2.0) * steady / rev.stiffness_nm_per_rad
    assert dahl < back < 1e-3, (back, dahl)


def test_closed_cycles_do_non_negative_work(model):
    rev = model()
    rng = np.random.default_rng(20_251_124)
    for cycle in range(10):
        rev.reset()
        # A random path of 2-6 legs of 400 equal steps each, back to the start exactly.
        legs = int(rng.integers(2, 7))
        targets = [(rng.random() - 0.5) * 10.0 ** (-4.0 + 2.0 * rng.random()) for _ in range(legs - 1)] + [0.0]
        theta = np.concatenate(
            [np.linspace(a, b, 401)[1:] for a, b in zip([0.0] + targets[:-1], targets)]
        )
        theta[-1] = 0.0
        rotation = np.diff(theta, prepend=0.0)
        torque = rev.series(rotation, 1e-3)
        # Trapezoids of torque x rotation; the relaxed state's torque is 0 (no axial load, no seals).
        work = np.sum(0.5 * (np.concatenate([[0.0], torque[:-1]]) + torque) * rotation)
        assert work >= -1e-12, f"cycle {cycle}: work {work:.3e} J"
    # Hysteresis: an oscillation of +-1 mrad about the steady forward state draws a loop of
    # positive area.
    rev.reset(speed_rpm=1.0)
    theta = 1e-3 * np.sin(2.0 * math.pi * np.arange(4001) / 1000.0)
    torque = rev.series(np.diff(theta, prepend=0.0), 1e-3)
    loop = np.sum(0.5 * (torque[1000:-1] + torque[1001:]) * np.diff(theta[1000:]))
    assert loop > 0.0


def test_stiffness_is_the_slope_from_rest(model):
    rev = model()
    stiffness = rev.stiffness_nm_per_rad
    # Dahl's curve is linear to sigma dtheta / (2 g): 4e-6 here for the ball-ball contacts, the
    # stiffest mechanism of the least friction.
    dtheta = 1e-13
    for sign in (1.0, -1.0):
        rev.reset()
        slope = rev.step(sign * dtheta, 1e-3) / (sign * dtheta)
        assert slope == pytest.approx(stiffness, rel=1e-5)
    # After a reversal from steady running at the same speed the slope starts near twice it
    # (each state's stiffness times 1 + g_before / g_after: exactly twice where each state's
    # steady friction is the same both ways; a nut's shares of the mechanisms are not, 2.01 here).
    rpm = 100.0
    rev.reset(speed_rpm=rpm)
    before = rev.friction_nm
    rev.step(-dtheta, dtheta / rad_s(rpm))
    slope = (before - rev.friction_nm) / dtheta
    assert 1.9 * stiffness < slope < 2.1 * stiffness


def test_reset(screw, model, precision):
    rev = model(precision)
    for rpm in (100.0, -300.0):
        rev.reset(speed_rpm=rpm)
        # No axial load and no seals: the friction held is the whole torque.
        assert rev.friction_nm == pytest.approx(screw.torque(2000.0, speed_rpm=rpm), rel=RTOL[precision])
    rev.reset()
    assert rev.friction_nm == 0.0
    # A reset forgets everything: the same steps give the same torques, bit for bit.
    rotation, dt = reversal_path(0.002, 10.0, 50)
    first = rev.series(rotation, dt)
    rev.series(-rotation, 0.3 * dt)
    rev.reset()
    np.testing.assert_array_equal(rev.series(rotation, dt), first)
    # A refused reset keeps the state.
    held = rev.friction_nm
    with pytest.raises(ValueError, match=r"invalid speed_rpm: 0 \(valid: nonzero"):
        rev.reset(speed_rpm=0.0)
    assert rev.friction_nm == held
    rev.reset(speed_rpm=None)
    assert rev.friction_nm == 0.0


@pytest.mark.parametrize(
    "rotation, dt, name",
    [
        (math.nan, 1e-3, "rotation_rad"),
        (math.inf, 1e-3, "rotation_rad"),
        (1e-3, 0.0, "dt_s"),
        (1e-3, -1e-3, "dt_s"),
        (1e-3, math.nan, "dt_s"),
        (1e300, 1e-300, "rotation_rad"),
        (True, 1e-3, "rotation_rad"),
        (1e-3, False, "dt_s"),
        ("0.001", 1e-3, "rotation_rad"),
        (1e-3, 1e-3 + 0j, "dt_s"),
        (1e-3, None, "dt_s"),
        (np.datetime64("2025-01-01"), 1e-3, "rotation_rad"),
        (np.ma.masked_array([1e-3], mask=[True]), 1e-3, "rotation_rad"),
    ],
)
def test_bad_steps_are_value_errors_naming_the_argument(model, rotation, dt, name):
    rev = model()
    with pytest.raises(ValueError, match=rf"invalid {name}: .*\(valid: "):
        rev.step(rotation, dt)
    with pytest.raises(ValueError, match=rf"invalid {name}: "):
        rev.series(rotation, dt)
    assert rev.friction_nm == 0.0  # nothing stepped
    assert rev.step(1e-5, 1e-3) > 0.0  # still usable


def test_f32_refuses_a_time_step_it_cannot_hold(model):
    with pytest.raises(ValueError, match=r"invalid dt_s: 1e-50 s \(valid: finite and > 0 in f32"):
        model("f32").step(1e-3, 1e-50)
    assert math.isfinite(model("f64").step(1e-60, 1e-50))


def test_bad_step_in_a_series_names_its_index_and_steps_nothing(model):
    rev = model()
    rotation = np.full((2, 3), 1e-5)
    dt = np.array([1e-3, 1e-3, 0.0])
    with pytest.raises(ValueError, match=r"invalid dt_s: 0 s \(valid: finite and > 0\) at index \(0, 2\) of the steps \(shape \(2, 3\)\)"):
        rev.series(rotation, dt)
    rotation[1, 1] = math.nan
    with pytest.raises(ValueError, match=r"invalid rotation_rad: NaN .* at index \(1, 1\)"):
        rev.series(rotation, 1e-3)
    assert rev.friction_nm == 0.0
    with pytest.raises(ValueError, match=r"do not broadcast.*rotation_rad \(3,\).*dt_s \(2,\)"):
        rev.series([1e-5, 1e-5, 1e-5], [1e-3, 1e-3])
    with pytest.raises(ValueError, match=r"invalid rotation_rad: .*\(valid: a real number\)"):
        rev.step([1e-5, 1e-5], 1e-3)


@pytest.mark.parametrize("speed, pattern", [
    (0, r"invalid speed_rpm: 0 \(valid: nonzero"),
    (math.nan, r"invalid speed_rpm: NaN \(valid: finite"),
    (1e9, r"invalid speed_rpm: 1e9 \(valid: finite, \|speed\| <= 30000 rpm"),
    (True, r"invalid speed_rpm: True \(valid: a real number"),
    ("100", r"invalid speed_rpm: '100'"),
])
def test_bad_reset_speeds_are_value_errors(model, precision, speed, pattern):
    with pytest.raises(ValueError, match=pattern):
        model(precision).reset(speed_rpm=speed)


@pytest.mark.parametrize(
    "kwargs, pattern",
    [
        (dict(preload_n=math.nan), r"invalid preload_n: NaN \(valid: "),
        (dict(preload_n=-5.0), r"invalid preload_n: -5 N \(valid: "),
        (dict(preload_n=True), r"invalid preload_n: True \(valid: a real number"),
        (dict(preload_n=1.0), r"invalid preload_n: 1 N \(valid: every loaded ball above 0.5 N"),
        (dict(axial_load_n="0"), r"invalid axial_load_n: '0'"),
        (dict(axial_load_n=math.inf), r"invalid axial_load_n: inf \(valid: "),
        (dict(precision="f16"), r"invalid precision: 'f16' \(valid: \"f64\", \"f32\"\)"),
        (dict(precision=64), r"invalid precision: 64 "),
    ],
)
def test_bad_construction_is_a_value_error_naming_the_argument(screw, kwargs, pattern):
    with pytest.raises(ValueError, match=pattern):
        ballscrew.Reversal(screw, **kwargs)


def test_unsupported_specs_are_refused_naming_the_field(screw):
    seals = ballscrew.Screw.from_toml_str(screw.to_toml() + "\n[extensions.seal_drag]\ntorque_nm = 0.01\n")
    with pytest.raises(ValueError, match=r"invalid extensions: .*\(valid: none, for the reversal model\)"):
        ballscrew.Reversal(seals)
    fastsim = ballscrew.Screw.from_toml_str(
        screw.to_toml().replace('contact_theory = "linear-saturated"', 'contact_theory = "fastsim"')
    )
    with pytest.raises(ValueError, match=r"invalid model\.contact_theory: fastsim"):
        ballscrew.Reversal(fastsim)
    with pytest.raises(TypeError):
        ballscrew.Reversal("dkfzd4012")


def test_no_quasi_static_state_is_a_convergence_error(screw):
    # Dry, 16 N between neighbouring balls: the lightest circle's balls skid at 2000 N.
    text = screw.to_toml().replace('lubrication = "ehl"', 'lubrication = "dry"')
    skid = ballscrew.Screw.from_toml_str(text.replace("[friction]\n", "[friction]\nball_ball_load_n = 16.0\n", 1))
    with pytest.raises(ballscrew.ConvergenceError, match=r"did not converge .*preload_n 2000"):
        ballscrew.Reversal(skid, 2000.0)


def test_signature_and_docstrings():
    params = inspect.signature(ballscrew.Reversal).parameters
    assert list(params) == ["screw", "preload_n", "axial_load_n", "precision", "audit_every"]
    assert params["precision"].default == "f64" and params["preload_n"].default is None
    assert params["audit_every"].default == 1000 and params["audit_every"].kind is inspect.Parameter.KEYWORD_ONLY
    assert ballscrew.Reversal.__doc__ and "N m" in ballscrew.Reversal.__doc__
    for name in dir(ballscrew.Reversal):
        if not name.startswith("_"):
            assert getattr(ballscrew.Reversal, name).__doc__, name
    for name in ("step", "series"):
        doc = getattr(ballscrew.Reversal, name).__doc__
        assert "N m" in doc and "rad" in doc and "(s" in doc, name


def test_series_releases_the_gil(model, assert_releases_the_gil):
    rev = model()
    # Small oscillations through reversals, 40,000 steps: about 0.17 s in all (10,000 took
    # 0.04 s, too short for the watch to be sure).
    rotation = np.diff(1e-4 * np.sin(np.linspace(0.0, 200.0 * math.pi, 40_000)), prepend=0.0)
    assert_releases_the_gil(lambda: rev.series(rotation, 1e-3))


def test_no_load_on_the_balls_is_refused_as_by_the_command_line(screw):
    # `ballscrew reversal --preload-n 0` and the Python object give the same answer: the core's
    # refusal of a point where no ball carries a load (no friction to reverse).
    message = r"invalid preload_n: 0 N \(valid: a load on the balls \(a preload, or an axial load\)"
    with pytest.raises(ValueError, match=message):
        ballscrew.Reversal(screw, preload_n=0.0)
    with pytest.raises(ValueError, match=message):
        ballscrew.Reversal(screw, preload_n=0.0, axial_load_n=0.0, precision="f32")
    # Without a preload but with an axial load, one nut carries it.
    assert ballscrew.Reversal(screw, preload_n=0.0, axial_load_n=500.0).stiffness_nm_per_rad > 0.0


def test_the_audit_compares_the_steady_torque_of_every_nth_turning_step(screw, precision):
    # 25 turning steps through a reversal and 3 that do not turn, audited every 10th turning
    # step (the 1st, 11th, 21st): the steady torque each settles on is the canonical one on the
    # built-in screw, so nothing departs and nothing is said.
    rev = ballscrew.Reversal(screw, 2000.0, 100.0, precision, audit_every=10)
    steps = np.concatenate([np.full(12, 2e-4), np.zeros(3), np.full(13, -2e-4)])
    with warnings.catch_warnings():
        warnings.simplefilter("error", ballscrew.StateWarning)
        rev.series(steps, 1e-3)
    a = rev.audit
    assert (a["audit_every"], a["calls"], a["audited"], a["departed"], a["first_departure"]) == (10, 25, 3, 0, None)
    assert 0.0 < a["largest_departure"] <= a["tolerance"] == (1e-6 if precision == "f64" else 5e-4)
    rev.reset()
    assert (rev.audit["calls"], rev.audit["audited"]) == (0, 0)
    assert ballscrew.Reversal(screw).audit["audit_every"] == 1000
    assert ballscrew.Reversal(screw, audit_every=0).series(steps, 1e-3).shape == (28,)


@pytest.mark.parametrize("bad", [-1, 0.5, "1", 2**32])
def test_bad_audit_every_is_a_value_error_naming_it(screw, bad):
    with pytest.raises(ValueError, match=r"invalid audit_every: .* \(valid: a whole number in \[0, 4294967295\]"):
        ballscrew.Reversal(screw, audit_every=bad)

"""Preload arrangements (`geometry.preload`) through Python: the single-nut 16 x 5 screw with
oversize balls (configs/single-nut-16x5.toml), its drag in both directions, and the refusals
that name the field."""

import pathlib
import pickle

import pytest

import ballscrew

CONFIG = pathlib.Path(__file__).resolve().parents[3] / "configs" / "single-nut-16x5.toml"


@pytest.fixture(scope="module")
def screw():
    return ballscrew.Screw.from_toml(CONFIG)


def test_the_arrangement_is_read(screw):
    assert screw.preload_arrangement == "oversize-ball"
    assert (screw.nuts, screw.circles_per_nut, screw.balls_per_circle) == (1, 3, 15)
    assert ballscrew.Screw.dkfzd4012().preload_arrangement == "double-nut"
    assert "preload oversize-ball, 1 nut(s) x 3 circles x 15 balls" in repr(screw)


def test_four_point_drag_reverses_with_the_direction(screw):
    forward = screw.summary(200.0, speed_rpm=1000.0)
    backward = screw.summary(200.0, speed_rpm=-1000.0)
    assert forward["drag_torque_nm"] > 0.0
    # Without axial load the two directions mirror each other.
    assert backward["drag_torque_nm"] == pytest.approx(-forward["drag_torque_nm"], rel=1e-9)
    assert forward["load_torque_nm"] == 0.0


def test_a_nut_without_preload_refuses_one():
    text = CONFIG.read_text().replace('preload = "oversize-ball"', 'preload = "none"')
    with pytest.raises(ValueError, match=r"operating\.preload_n"):
        ballscrew.Screw.from_toml_str(text, "none.toml")
    screw = ballscrew.Screw.from_toml_str(text.replace("preload_n = 200.0", "preload_n = 0.0"), "none.toml")
    with pytest.raises(ValueError, match=r"preload_n"):
        screw.summary(200.0, speed_rpm=1000.0)
    row = screw.summary(0.0, speed_rpm=1000.0, axial_load_n=300.0)
    assert row["drag_torque_nm"] > 0.0


def test_the_evaluator_solves_four_point_balls_on_the_model(screw):
    # The control-loop evaluator does not take four-point balls: in f64 the Evaluator runs on
    # the model's own solve (as the FMU does), in f32 it refuses, naming the option.
    with pytest.raises(ValueError, match=r'precision "f32" needs the control-loop evaluator.*geometry\.preload.*oversize-ball'):
        ballscrew.Evaluator(screw, "f32")
    ev = ballscrew.Evaluator(screw)
    assert (ev.solver, ev.precision) == ("model", "f64")
    assert "on the model" in repr(ev) and "on the evaluator" in repr(ballscrew.Evaluator(ballscrew.Screw.dkfzd4012()))
    # A short drive cycle through a reversal, with an axial load: Screw.torque's torques.
    speeds = [1000.0, 300.0, 10.0, -10.0, -300.0, -1000.0]
    axial = [0.0, 100.0, 200.0, 200.0, -100.0, 0.0]
    got = [ev.torque(200.0, speed_rpm=s, axial_load_n=a) for s, a in zip(speeds, axial)]
    want = [screw.torque(200.0, speed_rpm=s, axial_load_n=a) for s, a in zip(speeds, axial)]
    assert got == pytest.approx(want, rel=1e-8)
    assert got[0] > 0.0 > got[-1]
    # A series equals the scalar calls in the same order, bit for bit, from the same state.
    ev.reset()
    series = ev.series(200.0, speed_rpm=speeds, axial_load_n=axial)
    ev.reset()
    assert list(series) == [ev.torque(200.0, speed_rpm=s, axial_load_n=a) for s, a in zip(speeds, axial)]
    # A copy is an evaluator of the same kind.
    assert pickle.loads(pickle.dumps(ev)).solver == "model"

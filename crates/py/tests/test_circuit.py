"""A circuit of several loaded turns (an external return): the model's ball train on every
Python path, the same number as the command line, and an error where the train has no steady
state (docs/model-notes.md, "The ball train")."""

import json

import numpy as np
import pytest

import ballscrew


@pytest.fixture(scope="module")
def screw():
    return ballscrew.Screw.dkfzd4012().replace({"circulation.return": "external"})


def test_scalar_batch_and_evaluator_give_the_same_bits(screw):
    t = screw.torque(2000.0, speed_rpm=100.0)
    batch = screw.torque(np.array([1000.0, 2000.0]), speed_rpm=np.array([10.0, 100.0]))
    assert batch[1] == t
    ev = ballscrew.Evaluator(screw)
    assert ev.solver == "model"
    assert ev.torque(2000.0, speed_rpm=100.0) == t
    # The train lifts the drag above the internal return's.
    assert t > ballscrew.Screw.dkfzd4012().torque(2000.0, speed_rpm=100.0) * 1.2


def test_the_command_line_gives_the_same_number(cli, repo_root, tmp_path):
    text = (repo_root / "configs" / "dkfzd4012.toml").read_text()
    spec = tmp_path / "external.toml"
    spec.write_text(text.replace('return = "internal" ', 'return = "external" ', 1))
    screw = ballscrew.Screw.from_toml(spec)
    assert screw.to_toml().count('return = "external"') == 1
    out = json.loads(cli("--spec", str(spec), "torque", "--format", "json"))
    # The command reports the summary (Python's summary to the bit); the scalar torque sums the
    # same balls in another order, within rounding.
    assert out["torque_nm"] == screw.summary(preload_n=2000.0)["torque_nm"]
    assert out["ball_ball_torque_nm"] == screw.summary(preload_n=2000.0)["ball_ball_torque_nm"]
    assert out["torque_nm"] == pytest.approx(screw.torque(2000.0, speed_rpm=100.0), rel=1e-14)


def test_no_steady_train_raises_convergence_error_or_gives_nan(screw):
    with pytest.raises(ballscrew.ConvergenceError, match="ball train of the circuit of nut"):
        screw.torque(2000.0, speed_rpm=3000.0)
    with pytest.warns(ballscrew.EvaluationWarning):
        t = screw.torque(np.array([2000.0, 2000.0]), speed_rpm=np.array([100.0, 3000.0]), errors="nan")
    assert np.isfinite(t[0]) and np.isnan(t[1])


def test_f32_is_refused_naming_the_key(screw):
    with pytest.raises(ValueError, match="circulation.turns_per_circuit"):
        ballscrew.Evaluator(screw, precision="f32")


def _on_the_model_on_every_path(screw, key, speed_rpm):
    """The torque of `screw` at 2000 N and `speed_rpm`, after checking that the evaluator leaves
    it to the model (f64: the scalar's torque, as the batch's) and refuses it in f32, naming
    `key`."""
    t = screw.torque(2000.0, speed_rpm=speed_rpm)
    ev = ballscrew.Evaluator(screw)
    assert ev.solver == "model"
    assert ev.torque(2000.0, speed_rpm=speed_rpm) == t
    assert screw.torque(np.array([1000.0, 2000.0]), speed_rpm=speed_rpm)[1] == t
    with pytest.raises(ValueError, match=key):
        ballscrew.Evaluator(screw, precision="f32")
    return t


def test_a_lead_deviation_runs_on_the_model_on_every_path():
    """A stated lead deviation (`circulation.lead_deviation_um`) moves load between the circles:
    the evaluator leaves it to the model (f64) and refuses it in f32, naming the key; the torque
    is the scalar's on every path, and the free orbit ratio is in the records."""
    screw = ballscrew.Screw.dkfzd4012().replace({"circulation.lead_deviation_um": -2.0})
    t = _on_the_model_on_every_path(screw, "circulation.lead_deviation_um", 100.0)
    assert t != ballscrew.Screw.dkfzd4012().torque(2000.0, speed_rpm=100.0)
    with pytest.raises(ValueError, match="lead_deviation_um"):
        ballscrew.Screw.dkfzd4012().replace({"circulation.lead_deviation_um": 500.0})
    rows = screw.inspect(2000.0)
    # A circuit of one turn: each ball is free, its free orbit ratio its orbit ratio.
    assert all(r["free_orbit_ratio"] == r["orbit_ratio"] for r in rows)


def test_a_load_ramp_runs_on_the_model_on_every_path():
    """A stated load ramp (`circulation.load_ramp_balls`): the evaluator leaves it to the model
    (f64) and refuses it in f32, naming the key; the torque is the scalar's on every path and
    lies above the screw's without a ramp (the train carries the ramp's mismatch); a ramp out of
    range or one that leaves a circle no full ball is a ValueError naming the key; a circle's
    record counts its full balls only."""
    screw = ballscrew.Screw.dkfzd4012().replace({"circulation.load_ramp_balls": 2})
    t = _on_the_model_on_every_path(screw, "circulation.load_ramp_balls", 10.0)
    plain = ballscrew.Screw.dkfzd4012()
    assert t > plain.torque(2000.0, speed_rpm=10.0)
    for bad in (5, 2.5, -1):
        with pytest.raises(ValueError, match="load_ramp_balls"):
            ballscrew.Screw.dkfzd4012().replace({"circulation.load_ramp_balls": bad})
    with pytest.raises(ValueError, match="load_ramp_balls"):
        ballscrew.Screw.dkfzd4012().replace(
            {"circulation.load_ramp_balls": 4, "geometry.balls_per_circle": 8}
        )
    rows = screw.inspect(2000.0, speed_rpm=10.0)
    z = plain.inspect(2000.0, speed_rpm=10.0)[0]["balls"]
    assert all(r["balls"] == z - 4 and r["ramp_balls"] == 4 for r in rows)
    # The circle's load: its full balls' and its ramps' (half as many full balls').
    assert all(r["circle_axial_load_n"] == pytest.approx(r["axial_load_n"] * (z - 2)) for r in rows)


def test_spacer_balls_carry_the_chain_without_friction():
    """Spacer balls (`circulation.spacer_balls`): no friction between balls, so no ball-ball
    share; the control-loop evaluator takes them (a circuit of one turn) within its 1e-8 of the
    model; a value that is not a bool is a ValueError naming the key."""
    screw = ballscrew.Screw.dkfzd4012().replace({"circulation.spacer_balls": True})
    s = screw.summary(preload_n=2000.0, speed_rpm=100.0)
    assert s["ball_ball_torque_nm"] == 0.0
    assert s["torque_nm"] < ballscrew.Screw.dkfzd4012().summary(preload_n=2000.0, speed_rpm=100.0)["torque_nm"]
    ev = ballscrew.Evaluator(screw)
    assert ev.solver != "model"
    assert ev.torque(2000.0, speed_rpm=100.0) == pytest.approx(screw.torque(2000.0, speed_rpm=100.0), rel=1e-8)
    with pytest.raises(ValueError, match="spacer_balls"):
        ballscrew.Screw.dkfzd4012().replace({"circulation.spacer_balls": "yes"})

"""ballscrew.QuasiStaticWarning: where the balls' inertia, which the quasi-static model leaves out,
is not small, every call that gives torques at those speeds warns once, with the command line's
text; at ordinary speeds nothing warns."""

import subprocess
import warnings

import numpy as np
import pytest

import ballscrew

SCREW = ballscrew.Screw.dkfzd4012()
# DKFZD4012 at 500 N of preload: the gyroscopic share passes a quarter at about 4650 rpm.
WORST = "at speed 6000 rpm, preload 500 N, axial load 0 N: the most loaded ball's gyroscopic moment is 42 %"


def test_is_a_user_warning():
    assert issubclass(ballscrew.QuasiStaticWarning, UserWarning)
    assert not issubclass(ballscrew.QuasiStaticWarning, ballscrew.EvaluationWarning)


@pytest.mark.parametrize(
    "call",
    [
        lambda: SCREW.torque(500.0, speed_rpm=6000.0),
        lambda: SCREW.summary(500.0, speed_rpm=6000.0),
        lambda: SCREW.inspect(500.0, speed_rpm=6000.0),
        lambda: ballscrew.Evaluator(SCREW).torque(500.0, speed_rpm=6000.0),
    ],
    ids=["torque", "summary", "inspect", "evaluator"],
)
def test_one_point_names_it(call):
    with pytest.warns(ballscrew.QuasiStaticWarning) as record:
        call()
    assert len(record) == 1
    w = record[0].message
    assert str(w).startswith(WORST), str(w)
    assert (w.count, w.total, w.speed_rpm, w.preload_n, w.axial_load_n) == (1, 1, 6000.0, 500.0, 0.0)
    # Issued at the caller's line.
    assert record[0].filename == __file__


def test_a_batch_warns_once_naming_the_worst_of_how_many():
    speeds = np.array([1000.0, -6000.0, 5000.0, 3000.0])
    for call in [
        lambda: SCREW.torque(np.array([500.0, 2000.0])[:, None], speed_rpm=speeds),
        lambda: ballscrew.Evaluator(SCREW).series(np.array([500.0, 2000.0])[:, None], speed_rpm=speeds),
    ]:
        with pytest.warns(ballscrew.QuasiStaticWarning) as record:
            out = call()
        assert out.shape == (2, 4) and np.isfinite(out).all()
        assert len(record) == 1
        w = record[0].message
        # 5000 and 6000 rpm at 500 N; at 2000 N the balls carry about four times the load and none
        # is beyond.
        assert str(w).startswith("at 2 of 8 points, the worst at speed -6000 rpm, preload 500 N"), str(w)
        assert (w.count, w.total, w.speed_rpm) == (2, 8, -6000.0)


def test_sweep_and_torque_warn_with_the_command_lines_text(cli):
    # The command line prints the same text after `warning: ` on stderr.
    def stderr(*args):
        return subprocess.run([str(cli.path), *args], check=True, capture_output=True, text=True).stderr

    with pytest.warns(ballscrew.QuasiStaticWarning) as record:
        table = SCREW.sweep(speed_rpm=6000.0, frame=False)
    assert len(record) == 1 and len(table["preload_n"]) == 26
    assert "of 26 points, the worst at speed 6000 rpm, preload 500 N" in str(record[0].message)
    assert stderr("sweep", "--speed-rpm", "6000", "--format", "csv") == f"warning: {record[0].message}\n"
    with pytest.warns(ballscrew.QuasiStaticWarning) as record:
        SCREW.torque(0.0, speed_rpm=-2000.0)
    args = ["torque", "--speed-rpm", "-2000", "--preload-n", "0", "--format", "csv"]
    assert stderr(*args) == f"warning: {record[0].message}\n"


def test_predict_warns_once_with_the_command_lines_text(cli, tmp_path):
    data = tmp_path / "ops.csv"
    data.write_text("preload_n,speed_rpm\n2000,100\n500,6000\n500,-5000\n")
    with pytest.warns(ballscrew.QuasiStaticWarning) as record:
        out = ballscrew.predict(str(data))
    assert len(record) == 1 and np.isfinite(out).all() and len(out) == 3
    w = record[0].message
    assert str(w).startswith("at 2 of 3 points, the worst at speed 6000 rpm, preload 500 N"), str(w)
    o = subprocess.run([str(cli.path), "predict", "--data", str(data)], check=True, capture_output=True, text=True)
    assert o.stderr == f"warning: {w}\n"
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        ballscrew.predict({"preload_n": [2000.0, 500.0], "speed_rpm": [100.0, -3000.0]})


def test_zero_load_has_its_own_wording():
    with pytest.warns(ballscrew.QuasiStaticWarning, match="no ball carries a load, so only the balls' centrifugal force"):
        SCREW.torque(0.0, speed_rpm=2000.0)


def test_ordinary_speeds_do_not_warn():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        SCREW.torque(2000.0)
        SCREW.torque(np.linspace(500.0, 3000.0, 6)[:, None], speed_rpm=[3000.0, -3000.0, 10.0])
        SCREW.sweep(frame=False)
        SCREW.sweep(speed_rpm=-3000.0, frame=False)
        SCREW.summary(500.0, speed_rpm=3000.0)
        SCREW.inspect()
        ev = ballscrew.Evaluator(SCREW)
        ev.torque(2000.0, speed_rpm=300.0)
        ev.series(2000.0, speed_rpm=300.0 * np.sin(np.linspace(0.0, 6.0, 50)))
        SCREW.torque(2000.0, speed_rpm=0.0)


def test_a_warning_filter_turns_it_into_an_error():
    with warnings.catch_warnings():
        warnings.simplefilter("error", ballscrew.QuasiStaticWarning)
        with pytest.raises(ballscrew.QuasiStaticWarning):
            SCREW.torque(500.0, speed_rpm=6000.0)

"""predict and diagnose on tables in memory (pandas DataFrames, numpy structured arrays, dicts)
as on CSV files, and Python's own exceptions for files that cannot be read."""

import csv
import os
import pathlib
import sys

import numpy as np
import pytest

import ballscrew

ROOT = pathlib.Path(__file__).resolve().parents[3]
DATA = ROOT / "tests" / "data" / "xjtu-ball-screw" / "friction_torque.csv"
SPEC = ROOT / "configs" / "xjtu-32x8.toml"
MAP = {"time_h": "hours", "torque_nm": "upper_screw_torque_Nm"}
OPS = "preload_n,speed_rpm,axial_load_n\n2000,100,0\n1000,-300,50\n2500,30,-20\n"


@pytest.fixture
def ops_csv(tmp_path):
    path = tmp_path / "ops.csv"
    path.write_text(OPS)
    return path


def ops_columns():
    rows = list(csv.DictReader(OPS.splitlines()))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0]}


def test_predict_returns_a_numpy_array(ops_csv):
    got = ballscrew.predict(str(ops_csv))
    assert isinstance(got, np.ndarray) and got.dtype == np.float64 and got.shape == (3,)
    assert np.array_equal(ballscrew.predict(ops_columns()), got)


def test_predict_on_a_dataframe_equals_predict_on_its_csv(ops_csv):
    pd = pytest.importorskip("pandas")
    frame = pd.read_csv(ops_csv)
    frame.index = ["a", "b", "c"]
    got = ballscrew.predict(frame)
    assert isinstance(got, pd.Series) and got.name == "torque_nm" and list(got.index) == ["a", "b", "c"]
    assert np.array_equal(got.to_numpy(), ballscrew.predict(str(ops_csv)))
    # Integer columns, as pandas reads "2000", are real numbers too.
    assert frame["preload_n"].dtype.kind == "i"


def test_predict_on_a_structured_array_equals_predict_on_its_csv(ops_csv):
    cols = ops_columns()
    table = np.zeros(3, dtype=[(k, np.float64) for k in cols])
    for k, v in cols.items():
        table[k] = v
    assert np.array_equal(ballscrew.predict(table), ballscrew.predict(str(ops_csv)))


def test_dataframe_columns_are_checked_as_a_csvs(tmp_path):
    pd = pytest.importorskip("pandas")
    frame = pd.DataFrame({"preload_n": [2000.0, -5.0]})
    path = tmp_path / "bad.csv"
    frame.to_csv(path, index=False)
    with pytest.raises(ValueError) as from_file:
        ballscrew.predict(str(path))
    with pytest.raises(ValueError) as from_frame:
        ballscrew.predict(frame)
    # The same words, the file naming its line where the frame names its row.
    assert str(from_file.value).split("column `preload_n`")[1] == str(from_frame.value).split("column `preload_n`")[1]
    assert str(from_frame.value).startswith("row 2, column `preload_n`: -5 N is out of range")
    with pytest.raises(ValueError, match='invalid data column "preload_n"'):
        ballscrew.predict(pd.DataFrame({"preload_n": ["2000", "x"]}))
    with pytest.raises(ValueError, match="column names must be strings"):
        ballscrew.predict(pd.DataFrame({0: [2000.0]}))
    with pytest.warns(UserWarning, match="bogus"):
        ballscrew.predict(pd.DataFrame({"preload_n": [2000.0], "bogus": [1.0]}))


def test_diagnose_on_a_dataframe_equals_diagnose_on_its_csv():
    pd = pytest.importorskip("pandas")
    frame = pd.read_csv(DATA)
    from_frame = ballscrew.diagnose(frame, spec=str(SPEC), columns=MAP)
    from_file = ballscrew.diagnose(str(DATA), spec=str(SPEC), columns=MAP)
    # The warnings name the source ("data" or the path); everything else is the same, the
    # per-row torques a DataFrame on the frame's index for the frame.
    rows = from_frame.pop("row_torques")
    assert isinstance(rows, pd.DataFrame) and rows.index.equals(frame.index)
    for key, values in from_file.pop("row_torques").items():
        assert np.array_equal(rows[key].to_numpy(), values), key
    with np.printoptions(threshold=sys.maxsize, floatmode="unique"):
        assert repr({k: v for k, v in from_frame.items() if k != "warnings"}) == repr(
            {k: v for k, v in from_file.items() if k != "warnings"}
        )
    assert [f["effect"] for f in from_frame["findings"]] == ["preload_loss"]


@pytest.mark.parametrize(
    "call",
    [
        lambda p: ballscrew.Screw.from_toml(p),
        lambda p: ballscrew.predict(p),
        lambda p: ballscrew.predict({"preload_n": [2000.0]}, spec=p),
        lambda p: ballscrew.diagnose(p),
        lambda p: ballscrew.diagnose({"torque_nm": [0.1] * 10}, spec=p),
    ],
    ids=["from_toml", "predict", "predict-spec", "diagnose", "diagnose-spec"],
)
def test_files_that_cannot_be_read_raise_pythons_own_exceptions(tmp_path, call):
    missing = tmp_path / "nowhere.toml"
    with pytest.raises(FileNotFoundError) as e:
        call(str(missing))
    assert e.value.filename == str(missing) and "cannot read" in e.value.strerror
    with pytest.raises(IsADirectoryError):
        call(str(tmp_path))
    if os.name == "posix" and os.geteuid() != 0:
        locked = tmp_path / "locked.toml"
        locked.write_text("x")
        locked.chmod(0)
        with pytest.raises(PermissionError):
            call(str(locked))


def test_a_file_that_is_not_text_is_a_value_error(tmp_path):
    path = tmp_path / "binary.toml"
    path.write_bytes(b"\xff\xfe\x00bad")
    with pytest.raises(ValueError, match="binary.toml: cannot read spec file: not UTF-8 text"):
        ballscrew.Screw.from_toml(path)

"""ballscrew.diagnose: the report of `ballscrew diagnose --report` from Python, on a path or on columns."""

import csv
import json
import pathlib
import re

import numpy as np
import pytest

import ballscrew

ROOT = pathlib.Path(__file__).resolve().parents[3]
DATA = ROOT / "tests" / "data" / "xjtu-ball-screw" / "friction_torque.csv"
SPEC = ROOT / "configs" / "xjtu-32x8.toml"
MAP = {"time_h": "hours", "torque_nm": "upper_screw_torque_Nm"}


def columns():
    with DATA.open() as f:
        rows = list(csv.DictReader(f))
    return {"hours": [float(r["hours"]) for r in rows], "upper_screw_torque_Nm": [float(r["upper_screw_torque_Nm"]) for r in rows]}


def plain(value):
    """The report as JSON has it: numpy arrays as lists (NaN as None, as JSON writes it), the
    residuals' bins (columns) as records, the per-row torques (not in the command line's
    report) left out."""
    if isinstance(value, dict):
        return {k: records(v) if k == "bins" else plain(v) for k, v in value.items() if k != "row_torques"}
    if isinstance(value, list):
        return [plain(v) for v in value]
    if isinstance(value, np.ndarray):
        return [None if isinstance(v, float) and np.isnan(v) else v for v in value.tolist()]
    return value


def records(columns):
    """A dict of column arrays as the command line's list of records."""
    keys = list(columns)
    return [dict(zip(keys, row)) for row in zip(*(plain(columns[k]) for k in keys))]


def test_xjtu_path_finds_preload_loss_with_its_gain():
    r = ballscrew.diagnose(str(DATA), spec=str(SPEC), columns=MAP)
    assert [f["effect"] for f in r["findings"]] == ["preload_loss"]
    assert r["gain"]["heldout_rmse_cut"] >= 0.3
    assert r["baseline"]["spec_friction_coefficient"] == 0.03
    assert "unknown column" in r["warnings"][0]


def test_columns_give_the_same_report_as_the_path():
    by_path = ballscrew.diagnose(DATA, spec=SPEC, columns=MAP)
    by_columns = ballscrew.diagnose(columns(), spec=str(SPEC), columns=MAP)
    # Only the warning differs: the dict has no lower-screw column to ignore.
    by_path.pop("warnings")
    by_columns.pop("warnings")
    assert plain(by_path) == plain(by_columns)
    for key, values in by_path["row_torques"].items():
        assert np.array_equal(values, by_columns["row_torques"][key]), key


def test_same_report_as_the_command_line(cli):
    args = ["diagnose", "--spec", str(SPEC), "--data", str(DATA), "--format", "json"]
    for k, v in MAP.items():
        args += ["--column", f"{k}={v}"]
    r = ballscrew.diagnose(str(DATA), spec=str(SPEC), columns=MAP)
    want = json.loads(cli(*args))
    assert plain(r) == want
    # The tables of numbers are arrays, one per column; as records they are the JSON's.
    for mine, theirs in zip(r["residuals"], want["residuals"]):
        assert isinstance(mine["bins"]["mean_residual_nm"], np.ndarray)
        assert records(mine["bins"]) == theirs["bins"] and len(theirs["bins"]) == 5


def test_spec_may_be_a_screw_and_must_be_a_screw_or_a_path():
    screw = ballscrew.Screw.from_toml(SPEC)
    assert plain(ballscrew.diagnose(str(DATA), spec=screw, columns=MAP)) == plain(
        ballscrew.diagnose(str(DATA), spec=str(SPEC), columns=MAP)
    )
    assert np.array_equal(ballscrew.predict({"time_h": [0.0]}, spec=screw), ballscrew.predict({"time_h": [0.0]}, spec=str(SPEC)))
    with pytest.raises(ValueError, match="spec"):
        ballscrew.diagnose(str(DATA), spec=3.5, columns=MAP)


def test_bad_input_raises_value_error_naming_row_and_column():
    c = columns()
    c["upper_screw_torque_Nm"][4] = float("nan")
    with pytest.raises(ValueError, match=r"row 5, column `upper_screw_torque_Nm`"):
        ballscrew.diagnose(c, spec=str(SPEC), columns=MAP)
    with pytest.raises(ValueError, match="unknown column"):
        ballscrew.diagnose(columns(), columns={"hours_typo": "hours"})
    with pytest.raises(ValueError, match="no `torque_nm` column"):
        ballscrew.diagnose({"preload_n": [1000.0] * 10})
    with pytest.raises(ValueError, match="a CSV path, a dict of columns, a DataFrame"):
        ballscrew.diagnose(42)


def test_a_column_mapped_to_two_quantities_is_refused():
    # The axial load silently took the spec's 0 N: `Fp` fed only the first mapping.
    data = {"Fp": [1500.0], "speed_rpm": [300.0]}
    with pytest.raises(ValueError, match=r"column mappings preload_n=Fp and axial_load_n=Fp take the column `Fp` for two"):
        ballscrew.predict(data, columns={"preload_n": "Fp", "axial_load_n": "Fp"})
    t = ballscrew.predict(data, columns={"preload_n": "Fp"})
    assert t[0] == pytest.approx(ballscrew.Screw.dkfzd4012().torque(1500.0, speed_rpm=300.0), rel=1e-9)


def test_predict_names_the_row_the_model_cannot_evaluate():
    # At 0.01 N of preload the ball balance does not converge; the error names the row as
    # `ballscrew predict` does (from 1), after the good row before it. Its balls carry less than
    # their inertia (a QuasiStaticWarning says so first).
    with pytest.warns(ballscrew.QuasiStaticWarning), pytest.raises(ValueError, match=r"data row 2: .*did not converge"):
        ballscrew.predict({"preload_n": [2000.0, 0.01, 3000.0]})


def test_predict_uses_the_extended_spec_the_diagnosis_fits(tmp_path):
    # The extended spec of the XJTU diagnosis (written as `ballscrew diagnose --out-spec` does)
    # predicts the worn screw the diagnosis fitted, torque for torque.
    r = ballscrew.diagnose(str(DATA), spec=str(SPEC), columns=MAP)
    loss = r["findings"][0]["parameters"]["loss_per_1000_h"]
    # The default (lubricated) model calibrates the lubricant's full-film traction, not f.
    assert r["lubrication"] == "ehl"
    assert r["calibration"][0]["name"] == "full_film_traction"
    mu = r["extended"]["full_film_traction"]
    mu_bl = r["extended"]["boundary_friction"]
    text = SPEC.read_text() + f"\n[lubricant]\nfull_film_traction = {mu!r}\nboundary_friction = {mu_bl!r}\n"
    text += f"\n[extensions.preload_loss]\nloss_per_1000_h = {loss!r}\n"
    # The model is several times below this screw: a level factor carries what the oil's
    # physical friction cannot, and the extended spec carries the factor.
    factor = r["level"]["factor"]
    assert factor > 2 and not r["level"]["absorbed"]
    text += f"\n[extensions.level_factor]\nfactor = {factor!r}\n"
    spec = tmp_path / "extended.toml"
    spec.write_text(text)
    # At the data's first and last running times the spec predicts what the diagnosis's extended
    # model does (within 0.5 %: the diagnosis interpolates its tables), and the torque falls.
    with DATA.open(newline="") as f:
        hours = [float(row["hours"]) for row in csv.DictReader(f)]
    extended = r["row_torques"]["extended_torque_nm"]
    t0, t1 = ballscrew.predict({"time_h": [hours[0], hours[-1]]}, spec=str(spec))
    assert t0 == pytest.approx(extended[0], rel=5e-3) and t1 == pytest.approx(extended[-1], rel=5e-3)
    assert t1 < t0
    # Without the extension the spec's torque does not change with time.
    a, b = ballscrew.predict({"time_h": [0.0, 1000.0]}, spec=str(SPEC))
    assert a == b
    # The measured start (0.3985 N m) is met within the extended model's RMSE.
    assert abs(t0 - 0.3985) < 3 * r["extended"]["metrics"]["rmse_nm"]
    with pytest.raises(ValueError, match="time_h"):
        ballscrew.predict({"time_h": [-1.0]})


def test_spreadsheet_csv_bom_semicolons_and_crlf_read_as_the_original(tmp_path):
    # The XJTU data as a spreadsheet in a decimal-comma locale saves it (numbers kept with a
    # decimal point): a byte order mark, semicolons, CRLF. The delimiter is found or given.
    excel = tmp_path / "xjtu.csv"
    excel.write_bytes(b"\xef\xbb\xbf" + DATA.read_bytes().replace(b",", b";").replace(b"\n", b"\r\n"))
    original = plain(ballscrew.diagnose(str(DATA), spec=str(SPEC), columns=MAP))
    assert plain(ballscrew.diagnose(str(excel), spec=str(SPEC), columns=MAP)) == original
    assert plain(ballscrew.diagnose(excel, spec=str(SPEC), columns=MAP, delimiter=";")) == original
    ops = tmp_path / "ops.csv"
    ops.write_bytes(b"\xef\xbb\xbf# operating points\r\npreload_n;speed_rpm\r\n2000;100\r\n1000;-300\r\n")
    want = ballscrew.predict({"preload_n": [2000.0, 1000.0], "speed_rpm": [100.0, -300.0]})
    assert np.array_equal(ballscrew.predict(str(ops)), want)
    assert np.array_equal(ballscrew.predict(str(ops), delimiter="semicolon"), want)
    tabs = tmp_path / "ops.tsv"
    tabs.write_text("preload_n\tspeed_rpm\n2000\t100\n1000\t-300\n")
    assert np.array_equal(ballscrew.predict(str(tabs), delimiter="\t"), want)
    with pytest.raises(ValueError, match=r"invalid delimiter \"\|\""):
        ballscrew.predict(str(ops), delimiter="|")
    with pytest.raises(ValueError, match="only for a CSV path"):
        ballscrew.predict({"preload_n": [2000.0]}, delimiter=";")


def test_csv_errors_name_the_file_and_its_line(tmp_path):
    # A decimal comma, a value out of range and a row the model cannot evaluate, each on line 4
    # (1 N of preload under the paper's dry model, no load between balls; the lubricated default
    # and the ball train's loads balance it), as the command line's test has it.
    builtin = ballscrew.Screw.dkfzd4012().to_toml()
    paper = builtin.replace('lubrication = "ehl"', 'lubrication = "dry"', 1)
    dry = ballscrew.Screw.from_toml_str(paper.replace("[friction]\n", "[friction]\nball_ball_load_n = 0.0\n", 1))
    assert dry.lubrication == "dry"
    for name, row, says in [
        ("comma.csv", "1500,5;100", r"row 4, column `preload_n`: decimal comma in \"1500,5\""),
        ("range.csv", "-5;100", r"row 4, column `preload_n`: -5 N is out of range"),
        ("model.csv", "1;100", r"row 4: .*did not converge"),
    ]:
        path = tmp_path / name
        path.write_text(f"# ops\npreload_n;speed_rpm\n2000;100\n{row}\n")
        with pytest.raises(ValueError, match=f"^{re.escape(str(path))}: {says}"):
            ballscrew.predict(str(path), spec=dry)


def waviness_data():
    """DKFZD4012 over four leads of travel at three preloads and two speeds, its own model's torque
    with a waviness of the lead's 2nd harmonic and a little noise: data with positions, so the
    report has its periodogram."""
    rng = np.random.default_rng(7)
    n = 120
    lead_mm = 1e3 * ballscrew.Screw.dkfzd4012().lead_m
    data = {
        "preload_n": np.repeat([1000.0, 2000.0, 3000.0], n // 3),
        "speed_rpm": np.tile([100.0, -100.0], n // 2),
        "position_mm": rng.uniform(0.0, 4 * lead_mm, n),
    }
    model = ballscrew.predict(data)
    # Against the motion, as drag is.
    wave = 0.02 * np.sin(2 * np.pi * 2 * data["position_mm"] / lead_mm) * np.sign(data["speed_rpm"])
    data["torque_nm"] = model + wave + rng.normal(0.0, 0.002, n)
    return data


def test_tables_are_numpy_columns_and_rows_a_frame_on_the_data_index(cli, tmp_path):
    pd = pytest.importorskip("pandas")
    data = waviness_data()
    index = pd.Index([f"run{i:03d}" for i in range(len(data["torque_nm"]))][::-1], name="run")
    frame = pd.DataFrame(data, index=index)
    r = ballscrew.diagnose(frame)
    # Scalars stay Python scalars, records stay records.
    assert type(r["rows"]) is int and r["rows"] == 120
    assert type(r["baseline"]["rmse_nm"]) is float and type(r["verdict"]) is str
    assert isinstance(r["findings"], list) and isinstance(r["candidates"][0], dict)
    # Each residual's bins: one 1-d array per column, float64 (the counts int64), equal lengths.
    for residual in r["residuals"]:
        bins = residual["bins"]
        assert sorted(bins) == ["from", "mean_residual_nm", "rows", "to"]
        assert bins["mean_residual_nm"].dtype == np.float64 and bins["from"].dtype == np.float64
        assert bins["rows"].dtype == np.int64 and bins["rows"].sum() == 120
        assert {a.ndim for a in bins.values()} == {1} and len({len(a) for a in bins.values()}) == 1
    pg = r["position_periodogram"]
    assert pg["harmonic"].dtype == np.int64 and pg["harmonic"].tolist() == list(range(1, len(pg["harmonic"]) + 1))
    assert pg["baseline_amplitude_nm"].dtype == np.float64 and pg["baseline_amplitude_nm"].shape == pg["harmonic"].shape
    # The lead's 2nd harmonic stands out in the calibrated model's residual.
    assert int(pg["harmonic"][np.argmax(pg["baseline_amplitude_nm"])]) == 2
    # The per-row torques: a DataFrame on the data's index, the measured column the data's own.
    rows = r["row_torques"]
    assert isinstance(rows, pd.DataFrame) and rows.index.equals(frame.index)
    assert list(rows.columns) == ["measured_torque_nm", "spec_model_torque_nm", "calibrated_torque_nm", "extended_torque_nm"]
    assert (rows.dtypes == np.float64).all()
    assert np.array_equal(rows["measured_torque_nm"].to_numpy(), frame["torque_nm"].to_numpy())
    # The model as specified is the data's model, so its torque is `predict`'s.
    assert np.allclose(rows["spec_model_torque_nm"], ballscrew.predict(data), rtol=1e-6)
    # The report's RMSEs are those of these columns.
    for model, metrics in [("spec_model_torque_nm", r["spec_model"]), ("calibrated_torque_nm", r["baseline"])]:
        rmse = np.sqrt(np.mean((rows[model] - rows["measured_torque_nm"]) ** 2))
        assert rmse == pytest.approx(metrics["rmse_nm"], rel=1e-9), model
    assert np.sqrt(np.mean((rows["extended_torque_nm"] - rows["measured_torque_nm"]) ** 2)) == pytest.approx(
        r["extended"]["metrics"]["rmse_nm"], rel=1e-9
    )
    # The same data as a dict: the per-row torques as a dict of arrays, the rest the same; and
    # the command line's report on it as a CSV equals the arrays read as records.
    by_dict = ballscrew.diagnose(data)
    assert isinstance(by_dict["row_torques"], dict)
    assert np.array_equal(by_dict["row_torques"]["extended_torque_nm"], rows["extended_torque_nm"].to_numpy())
    path = tmp_path / "waviness.csv"
    frame.to_csv(path, index=False)
    want = json.loads(cli("diagnose", "--data", str(path), "--format", "json"))
    assert plain(r) == plain(by_dict)
    got = plain(r)
    assert got.pop("columns") == want.pop("columns")
    assert got == want


def test_predict_says_the_temperature_column_is_not_the_oil_temperature():
    # Under the lubricated model the oil at the contacts stays at the spec's temperature on every
    # row: the torques of 20 and 80 degrees C are the same, and a UserWarning says why.
    data = {"preload_n": [1500.0, 1500.0], "speed_rpm": [300.0, 300.0], "temperature_c": [20.0, 80.0]}
    with pytest.warns(UserWarning, match=r"oil at the contacts stays at the spec's lubricant.temperature_c \(40 degrees C\)"):
        out = ballscrew.predict(data)
    assert out[0] == out[1]

"""The lubricated model from Python: the oil temperature at the contacts (the command line's
`oil_temperature_c`), the spec's lubrication and lubricant, and the torque's shares by mechanism."""

import csv
import io
import json
import math

import numpy as np
import pytest

import ballscrew

RTOL = 1e-12
SHARES = [
    "creep_torque_nm",
    "rolling_resistance_torque_nm",
    "hysteresis_torque_nm",
    "ball_ball_torque_nm",
    "return_torque_nm",
]


@pytest.fixture(scope="module")
def screw():
    return ballscrew.Screw.dkfzd4012()


@pytest.fixture(scope="module")
def dry(screw):
    return ballscrew.Screw.from_toml_str(screw.to_toml().replace('lubrication = "ehl"', 'lubrication = "dry"'))


def same(a, b, rtol=RTOL):
    if a is None or b is None:  # JSON null: an undefined number (NaN), e.g. no efficiency without a load
        undefined = lambda x: x is None or (isinstance(x, float) and math.isnan(x))  # noqa: E731
        return undefined(a) and undefined(b)
    if isinstance(a, (int, str)) and isinstance(b, (int, str)):
        return a == b
    return a == b or abs(a - b) <= rtol * max(abs(a), abs(b))


def test_the_default_screw_is_lubricated_with_the_spec_files_lubricant(screw):
    assert screw.lubrication == "ehl"
    lubricant = screw.lubricant
    # ISO VG 68 at 40 C: the spec file's keys and units.
    assert lubricant["viscosity_40c_mm2_s"] == pytest.approx(68.0, rel=1e-12)
    assert lubricant["temperature_c"] == 40.0 == screw.oil_temperature_c
    assert {"viscosity_100c_mm2_s", "density_15c_kg_m3", "pressure_viscosity_per_gpa", "roughness_ball_rq_um",
            "boundary_friction", "full_film_traction", "hysteresis_loss_factor"} <= set(lubricant)
    assert screw.seal_torque_per_nut_nm == 0.0
    assert "lubrication ehl" in repr(screw) and "at 40 C" in repr(screw)


def test_a_spec_files_lubricant_reads_back(screw):
    text = screw.to_toml()
    start = text.index("[lubricant]")
    end = text.find("\n[", start + 1)
    lubricant = "[lubricant]\niso_vg = 32.0\ntemperature_c = 60.0\n"
    text = text[:start] + lubricant + (text[end + 1:] if end >= 0 else "")
    text = text.replace("seal_torque_per_nut_nm = 0.0", "seal_torque_per_nut_nm = 0.02")
    other = ballscrew.Screw.from_toml_str(text)
    assert other.lubricant["viscosity_40c_mm2_s"] == pytest.approx(32.0, rel=1e-12)
    assert other.oil_temperature_c == 60.0
    assert other.seal_torque_per_nut_nm == 0.02
    # Two nuts' seals, at a speed well above the standstill speed.
    assert other.summary()["seal_torque_nm"] == pytest.approx(0.04, rel=1e-12)
    # The table written back reads as the same oil (the grade's 100 C viscosity to the last bit
    # or so: mm^2/s to m^2/s and back).
    assert ballscrew.Screw.from_toml_str(other.to_toml()).lubricant == pytest.approx(other.lubricant, rel=1e-15)


def test_the_dry_model_has_no_oil(dry):
    assert dry.lubrication == "dry" and dry.oil_temperature_c is None
    assert "lubrication dry" in repr(dry)
    summary = dry.summary()
    assert summary["rolling_resistance_torque_nm"] == 0.0 and summary["hysteresis_torque_nm"] == 0.0


def test_a_speed_series_of_the_default_screw_rises_from_300_to_3000_rpm(screw):
    speeds = np.linspace(300.0, 3000.0, 10)
    torque = screw.torque(2000.0, speed_rpm=speeds)
    assert np.all(np.diff(torque) > 0), torque
    assert torque[-1] > 1.1 * torque[0]


@pytest.fixture(scope="module")
def cli_oil_sweep(cli):
    return json.loads(cli("sweep", "--oil-temperature-c", "20..80", "--speed-rpm", "1000", "--format", "json"))


def test_an_oil_temperature_sweep_falls_from_20_to_80_c_at_1000_rpm(screw):
    temps = np.arange(20.0, 81.0, 5.0)
    table = screw.sweep(oil_temperature_c=temps, speed_rpm=1000.0, frame=False)
    np.testing.assert_array_equal(table["oil_temperature_c"], temps)
    assert np.all(np.diff(table["torque_nm"]) < 0), table["torque_nm"]
    assert table["torque_nm"][0] > 1.1 * table["torque_nm"][-1]


def test_the_oil_temperature_sweep_is_the_command_lines(screw, cli_oil_sweep, cli):
    assert cli_oil_sweep["swept"] == "oil_temperature_c"
    temps = [r["oil_temperature_c"] for r in cli_oil_sweep["rows"]]
    assert temps == [20.0 + 5.0 * i for i in range(13)]
    table = screw.sweep(oil_temperature_c=temps, speed_rpm=1000.0, frame=False)
    rows = [{k: table[k][i].item() for k in table} for i in range(len(temps))]
    assert len(rows) == len(cli_oil_sweep["rows"])
    for i, (e, g) in enumerate(zip(cli_oil_sweep["rows"], rows)):
        assert list(e) == list(g), f"row {i}: keys differ"
        for k in e:
            assert same(e[k], g[k]), f"row {i}, {k}: command line {e[k]!r}, Python {g[k]!r}"
    header = next(csv.reader(io.StringIO(
        cli("sweep", "--oil-temperature-c", "20..30", "--speed-rpm", "1000", "--format", "csv"))))
    assert list(table) == header


def test_a_screw_at_another_oil_temperature_gives_the_sweeps_point(screw, cli_oil_sweep):
    row = cli_oil_sweep["rows"][8]  # 60 C
    warm = screw.with_oil_temperature(row["oil_temperature_c"])
    assert warm.oil_temperature_c == 60.0 and warm.lubricant["temperature_c"] == 60.0
    assert screw.oil_temperature_c == 40.0  # the original is unchanged
    assert warm.torque(2000.0, speed_rpm=1000.0) == pytest.approx(row["torque_nm"], rel=1e-9)
    assert warm.summary(speed_rpm=1000.0)["torque_nm"] == pytest.approx(row["torque_nm"], rel=1e-9)
    assert ballscrew.Evaluator(warm).torque(2000.0, 1000.0) == pytest.approx(row["torque_nm"], rel=1e-8)
    # A preload sweep at one oil temperature is that screw's sweep.
    a = screw.sweep([1000.0, 2000.0], speed_rpm=1000.0, oil_temperature_c=60.0, frame=False)
    b = warm.sweep([1000.0, 2000.0], speed_rpm=1000.0, frame=False)
    assert list(a) == list(b) and list(a)[0] == "preload_n"
    for k in a:
        np.testing.assert_array_equal(a[k], b[k])


def test_the_summary_shares_add_up_to_the_dissipation_torque(screw):
    for kwargs in [dict(), dict(preload_n=800.0, speed_rpm=3000.0, axial_load_n=300.0),
                   dict(preload_n=2500.0, speed_rpm=-250.0)]:
        s = screw.summary(**kwargs)
        # Every share acts against the motion: the sign of the speed.
        sign = math.copysign(1.0, s["speed_rpm"])
        assert sign * s["rolling_resistance_torque_nm"] > 0 and sign * s["hysteresis_torque_nm"] > 0
        assert sign * s["creep_torque_nm"] > 0
        assert math.fsum(s[k] for k in SHARES) == pytest.approx(s["dissipation_torque_nm"], rel=1e-12, abs=1e-15)


def test_the_contact_shares_add_up_to_the_contacts_torque_share(screw):
    rows = screw.inspect(2000.0, speed_rpm=1000.0)
    for r in rows:
        parts = r["creep_torque_share_nm"] + r["rolling_torque_share_nm"] + r["hysteresis_torque_share_nm"]
        assert parts == pytest.approx(r["torque_share_nm"], rel=1e-12, abs=1e-15)
    raceways = [r for r in rows if r["contact"] != "ball-ball"]
    assert all(r["film_central_um"] > r["film_minimum_um"] > 0 and r["lambda"] > 0 for r in raceways)
    assert all(0 < r["friction_coefficient"] <= 0.15 for r in raceways)


def test_an_oil_temperature_under_the_dry_model_is_refused(dry):
    with pytest.raises(ValueError, match=r"^invalid oil_temperature_c: 50 .*dry"):
        dry.with_oil_temperature(50.0)
    with pytest.raises(ValueError, match=r"^invalid oil_temperature_c: .*dry"):
        dry.sweep(oil_temperature_c=[20.0, 30.0], frame=False)
    with pytest.raises(ValueError, match=r"^invalid oil_temperature_c: .*dry"):
        dry.sweep([1000.0], oil_temperature_c=40.0, frame=False)


@pytest.mark.parametrize("value, given", [(250.0, "250"), (-40.0, "-40"), (math.nan, "NaN"), (math.inf, "inf")])
def test_an_oil_temperature_out_of_range_names_the_field_value_and_range(screw, value, given):
    expected = rf"^invalid oil_temperature_c: {given} \(valid: \[-30, 200\] degrees C\)"
    with pytest.raises(ValueError, match=expected):
        screw.with_oil_temperature(value)
    with pytest.raises(ValueError, match=expected):
        screw.sweep([1000.0], oil_temperature_c=value, frame=False)
    with pytest.raises(ValueError, match=rf"^invalid oil_temperature_c: {given} at index \(1,\) "):
        screw.sweep(oil_temperature_c=[40.0, value], frame=False)


def test_one_quantity_at_a_time_and_sweep_shapes(screw):
    with pytest.raises(ValueError, match="one quantity at a time: preload_n and oil_temperature_c"):
        screw.sweep([1000.0, 2000.0], oil_temperature_c=[20.0, 30.0], frame=False)
    with pytest.raises(ValueError, match=r"invalid oil_temperature_c: shape \(2, 2\) \(valid: a 1-d array"):
        screw.sweep(oil_temperature_c=np.full((2, 2), 40.0), frame=False)
    with pytest.raises(ValueError, match=r"invalid oil_temperature_c: shape \(0,\)"):
        screw.sweep(oil_temperature_c=[], frame=False)
    # One preload, given or the spec's, for an oil-temperature sweep.
    table = screw.sweep(1500.0, oil_temperature_c=[40.0], frame=False)
    assert table["torque_nm"][0] == pytest.approx(screw.torque(1500.0), rel=1e-9)
    table = screw.sweep(oil_temperature_c=np.array([40.0]), frame=False)
    assert table["torque_nm"][0] == pytest.approx(screw.torque(screw.default_preload_n), rel=1e-9)

"""The Python module gives the command line's numbers to the bit (the JSON's shortest round-trip
decimals): every stateless answer is the point's canonical state, the model's cold solve."""

import csv
import io
import json
import math

import numpy as np
import pytest

import ballscrew

RTOL = 0.0


def same(a, b, rtol=RTOL):
    """Equal within rtol (relative), JSON null standing for NaN, integers exactly."""
    if a is None or b is None:
        return (a is None or (isinstance(a, float) and math.isnan(a))) and (
            b is None or (isinstance(b, float) and math.isnan(b))
        )
    if isinstance(a, str) or isinstance(b, str):
        return a == b
    if isinstance(a, int) and isinstance(b, int):
        return a == b
    return a == b or abs(a - b) <= rtol * max(abs(a), abs(b))


def assert_rows_equal(expected, got):
    assert len(expected) == len(got)
    for i, (e, g) in enumerate(zip(expected, got)):
        assert list(e) == list(g), f"row {i}: keys differ"
        for k in e:
            assert same(e[k], g[k]), f"row {i}, {k}: command line {e[k]!r}, Python {g[k]!r}"


@pytest.fixture(scope="module")
def cli_sweep(cli):
    return json.loads(cli("sweep", "--format", "json"))


def test_sweep_matches_the_command_lines_default_sweep(cli_sweep):
    table = ballscrew.Screw.dkfzd4012().sweep(frame=False)
    n = len(table["preload_n"])
    rows = [{k: table[k][i].item() for k in table} for i in range(n)]
    assert n == 26  # 500..3000 N by 100 N
    assert_rows_equal(cli_sweep["rows"], rows)


def test_sweep_columns_are_the_command_lines_csv_columns(cli):
    header = next(csv.reader(io.StringIO(cli("sweep", "--format", "csv"))))
    assert list(ballscrew.Screw.dkfzd4012().sweep(frame=False)) == header


def test_batch_torque_matches_the_command_lines_sweep(cli_sweep):
    preloads = np.array([r["preload_n"] for r in cli_sweep["rows"]])
    torque = ballscrew.Screw.dkfzd4012().torque(preloads)
    expected = np.array([r["torque_nm"] for r in cli_sweep["rows"]])
    np.testing.assert_allclose(torque, expected, rtol=RTOL, atol=0)


@pytest.fixture(scope="module")
def cli_speed_sweep(cli):
    return json.loads(cli("sweep", "--speed-rpm", "-300..1500", "--speed-step-rpm", "300", "--preload-n", "1500",
                          "--format", "json"))


def test_a_speed_sweep_is_the_command_lines(cli_speed_sweep, cli):
    assert cli_speed_sweep["swept"] == "speed_rpm"
    speeds = [r["speed_rpm"] for r in cli_speed_sweep["rows"]]
    assert speeds == [-300.0, 0.0, 300.0, 600.0, 900.0, 1200.0, 1500.0]
    table = ballscrew.Screw.dkfzd4012().sweep(1500.0, speed_rpm=speeds, frame=False)
    rows = [{k: table[k][i].item() for k in table} for i in range(len(speeds))]
    assert_rows_equal(cli_speed_sweep["rows"], rows)
    header = next(csv.reader(io.StringIO(cli("sweep", "--speed-rpm", "100..200", "--format", "csv"))))
    assert list(ballscrew.Screw.dkfzd4012().sweep(speed_rpm=[100.0, 200.0], frame=False)) == header


def test_a_speed_sweep_is_the_torque_at_each_speed(cli_speed_sweep):
    screw = ballscrew.Screw.dkfzd4012()
    speeds = np.array([r["speed_rpm"] for r in cli_speed_sweep["rows"]])
    table = screw.sweep(1500.0, speed_rpm=speeds, frame=False)
    np.testing.assert_array_equal(table["speed_rpm"], speeds)
    np.testing.assert_array_equal(table["preload_n"], np.full(len(speeds), 1500.0))
    for speed, torque in zip(speeds, table["torque_nm"]):
        assert torque == screw.torque(1500.0, speed_rpm=speed)
    # The torque changes with the speed and its sign with the direction of rotation.
    assert table["torque_nm"][0] < 0.0 < table["torque_nm"][2] < table["torque_nm"][-1]
    # The spec's preload when none is given.
    default = screw.sweep(speed_rpm=speeds[:2], frame=False)
    np.testing.assert_array_equal(default["preload_n"], np.full(2, screw.default_preload_n))


def test_an_axial_load_sweep_is_the_command_lines(cli):
    doc = json.loads(cli("sweep", "--axial-load-n", "-1000..1000", "--axial-load-step-n", "1000", "--speed-rpm", "200",
                         "--format", "json"))
    assert doc["swept"] == "axial_load_n"
    loads = [r["axial_load_n"] for r in doc["rows"]]
    assert loads == [-1000.0, 0.0, 1000.0]
    screw = ballscrew.Screw.dkfzd4012()
    table = screw.sweep(speed_rpm=200.0, axial_load_n=np.array(loads), frame=False)
    rows = [{k: table[k][i].item() for k in table} for i in range(len(loads))]
    assert_rows_equal(doc["rows"], rows)
    for load, torque in zip(loads, table["torque_nm"]):
        assert torque == screw.torque(screw.default_preload_n, speed_rpm=200.0, axial_load_n=load)


def test_scalar_torque_and_summary_match_the_command_lines_torque(cli):
    for args, kwargs in [
        (["--preload-n", "2000"], dict(preload_n=2000.0)),
        (["--preload-n", "800", "--speed-rpm", "-250", "--axial-load-n", "300"],
         dict(preload_n=800.0, speed_rpm=-250.0, axial_load_n=300.0)),
    ]:
        out = json.loads(cli("torque", "--format", "json", *args))
        # The command's head: what it ran and, for a lubricated spec, the oil temperature at the
        # contacts (Python's summary is of a screw whose oil_temperature_c is a property).
        assert out["oil_temperature_c"] == ballscrew.Screw.dkfzd4012().oil_temperature_c
        head = ("command", "spec", "torque_route", "oil_temperature_c")
        expected = {k: v for k, v in out.items() if k not in head}
        screw = ballscrew.Screw.dkfzd4012()
        assert_rows_equal([expected], [screw.summary(**kwargs)])
        assert same(out["torque_nm"], screw.torque(**kwargs))


def flatten_inspect(doc):
    """The command line's nested inspect JSON as one row per contact (its CSV layout)."""
    rows = []
    for nut in doc["nuts"]:
        for circle in nut["circles"]:
            ball = {k: v for k, v in circle.items() if k != "contacts"}
            for contact in circle["contacts"]:
                rows.append({**ball, **contact})
    return rows


def test_inspect_matches_the_command_lines_inspect(cli):
    doc = json.loads(cli("inspect", "--format", "json", "--preload-n", "1500", "--axial-load-n", "-400"))
    rows = ballscrew.Screw.dkfzd4012().inspect(1500.0, axial_load_n=-400.0)
    assert len(rows) == 2 * 4 * 3  # nuts x circles x (nut, screw, ball-ball)
    assert_rows_equal(flatten_inspect(doc), rows)
    header = next(csv.reader(io.StringIO(cli("inspect", "--format", "csv", "--preload-n", "1500"))))
    assert list(rows[0]) == header


def test_a_spec_file_gives_the_command_lines_numbers(cli, tmp_path, repo_root):
    text = (repo_root / "configs" / "dkfzd4012.toml").read_text()
    text = text.replace('torque = "energy"', 'torque = "paper-eq27"').replace("coefficient = 0.03", "coefficient = 0.05")
    path = tmp_path / "variant.toml"
    path.write_text(text)
    doc = json.loads(cli("--spec", str(path), "sweep", "--preload", "500..3000", "--step", "500", "--format", "json"))
    screw = ballscrew.Screw.from_toml(path)
    assert screw.torque_route == "paper-eq27" and screw.friction_coefficient == 0.05
    table = screw.sweep([500.0, 1000.0, 1500.0, 2000.0, 2500.0, 3000.0], frame=False)
    rows = [{k: table[k][i].item() for k in table} for i in range(6)]
    assert_rows_equal(doc["rows"], rows)


def test_the_spin_creepage_has_one_name_and_unit_in_inspect_contact_and_python(cli):
    # inspect and contact of the command line, and Python's inspect records: 1/mm, named so.
    def spin_keys(obj):
        if isinstance(obj, dict):
            return {k for k in obj if k.startswith("creep_phi")} | set().union(*map(spin_keys, obj.values()))
        if isinstance(obj, list):
            return set().union(set(), *map(spin_keys, obj))
        return set()

    inspect = json.loads(cli("inspect", "--format", "json"))
    contact = json.loads(cli("contact", "--format", "json"))
    rows = ballscrew.Screw.dkfzd4012().inspect(2000.0)
    assert spin_keys(inspect) == spin_keys(contact) == spin_keys(rows) == {"creep_phi_per_mm"}
    # The same contact in both commands (the first nut's first circle, the nut contact): one value.
    first = [r for r in flatten_inspect(inspect) if r["creep_phi_per_mm"] is not None][0]
    assert same(first["creep_phi_per_mm"], next(spin_values(contact)))


def spin_values(obj):
    if isinstance(obj, dict):
        for k, v in obj.items():
            if k == "creep_phi_per_mm":
                yield v
            else:
                yield from spin_values(v)
    elif isinstance(obj, list):
        for v in obj:
            yield from spin_values(v)


def test_the_band_and_the_sensitivity_are_the_command_lines_to_the_bit(cli):
    # One band for one point on every path (docs/uncertainty.md): the same spec, point, sample
    # size and seed give the same bits from `torque --band`, `sweep --band`, `sensitivity` and
    # Python.
    screw = ballscrew.Screw.dkfzd4012()
    point = ["--preload-n", "1500", "--speed-rpm", "300"]
    torque = json.loads(cli("torque", *point, "--band", "10,90", "--samples", "32", "--seed", "4", "--format", "json"))
    band = screw.band(1500.0, 300.0, quantiles=(0.1, 0.9), samples=32, seed=4)
    for key, value in band.items():
        assert value == torque[key], key
    sweep = json.loads(cli("sweep", "--preload-n", "1000..2000", "--step", "500", "--speed-rpm", "300",
                           "--band", "10,90", "--samples", "32", "--seed", "4", "--format", "json"))
    table = screw.sweep(np.array([1000.0, 1500.0, 2000.0]), 300.0, band=(0.1, 0.9), samples=32, seed=4, frame=False)
    for i, row in enumerate(sweep["rows"]):
        for key in ("drag_torque_low_nm", "drag_torque_median_nm", "drag_torque_high_nm"):
            assert table[key][i] == row[key], (i, key)
    cli_s = json.loads(cli("sensitivity", *point, "--samples", "32", "--seed", "4", "--format", "json"))
    py_s = screw.sensitivity(1500.0, 300.0, samples=32, seed=4, frame=False)
    assert py_s.attrs["drag_torque_nm"] == cli_s["drag_torque_nm"]
    assert py_s.attrs["variance_nm2"] == cli_s["variance_nm2"]
    for i, row in enumerate(cli_s["inputs"]):
        for key, value in row.items():
            got = py_s[key][i]
            assert (got if isinstance(got, str) else float(got)) == value, (i, key)


def test_every_stateless_answer_is_the_points_own_to_the_bit():
    """A point's torque is its canonical state (the model's cold solve) on every path: scalar
    calls in either order on one Screw and each on a fresh one, an array, half of that array and
    a sweep give it the same bits, also at 1700-3100 rpm, where a ball of DKFZD4012 has two
    steady states over a range of loads (docs/model-notes.md item 24)."""
    rng = np.random.default_rng(40)
    n = 24
    preload = rng.uniform(500.0, 3000.0, n)
    speed = rng.uniform(1700.0, 3100.0, n) * rng.choice([-1.0, 1.0], n)
    axial = rng.uniform(-500.0, 500.0, n)
    screw = ballscrew.Screw.dkfzd4012()
    array = screw.torque(preload, speed, axial)
    forwards = [screw.torque(p, s, a) for p, s, a in zip(preload, speed, axial)]
    backwards = [screw.torque(p, s, a) for p, s, a in zip(preload[::-1], speed[::-1], axial[::-1])][::-1]
    fresh = [ballscrew.Screw.dkfzd4012().torque(p, s, a) for p, s, a in zip(preload, speed, axial)]
    half = screw.torque(preload[::2], speed[::2], axial[::2])
    for i in range(n):
        assert array[i] == forwards[i] == backwards[i] == fresh[i], i
    np.testing.assert_array_equal(half, array[::2])
    sweep = screw.sweep(speed_rpm=speed[:4], preload_n=preload[0], axial_load_n=axial[0], frame=False)
    for k in range(4):
        assert sweep["torque_nm"][k] == screw.torque(preload[0], speed[k], axial[0]), k
